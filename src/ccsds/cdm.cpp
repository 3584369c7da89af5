// CDM model and typed access to its states and covariances (include/evade/ccsds/cdm.hpp;
// CCSDS 508.0-B-1 tables 3-5 state vector, 3-6 covariance). Its keyword tables are
// cdm_keywords.cpp, its checks cdm_validation.cpp.
#include "evade/ccsds/cdm.hpp"

#include <cstdio>
#include <cstdlib>

#include <Eigen/Eigenvalues>

#include "evade/ccsds/internal/cdm_keyword_tables.hpp"
#include "evade/sgp4/text_fields.hpp"

namespace evade::ccsds {

std::string cdm_text_as_utf8(const std::string& text) {
  std::string out;
  long control = 0;
  const int at = sgp4::text_to_utf8(text, &out, &control, "\t\r\n");
  if (at == 0) return out;
  const auto pos = static_cast<std::size_t>(at - 1);
  const std::size_t nl = pos == 0 ? std::string::npos : text.rfind('\n', pos - 1);
  const std::size_t col0 = nl == std::string::npos ? pos : pos - nl - 1;
  long line = 1;
  for (std::size_t i = 0; i < pos; ++i) line += text[i] == '\n' ? 1 : 0;
  throw CdmError("CDM line " + std::to_string(line) + ", column " + std::to_string(col0 + 1) +
                 ": control character " + sgp4::code_point_name(control) +
                 "; expected printable text (UTF-8 or Latin-1)");
}

const CdmItem* CdmSection::find(const std::string& key) const {
  for (const auto& it : items)
    if (it.key == key) return &it;
  return nullptr;
}

CdmSection& CdmObject::section(CdmSectionId id) {
  return const_cast<CdmSection&>(static_cast<const CdmObject*>(this)->section(id));
}
const CdmSection& CdmObject::section(CdmSectionId id) const {
  switch (id) {
    case CdmSectionId::kOd: return od_parameters;
    case CdmSectionId::kAdditional: return additional_parameters;
    case CdmSectionId::kState: return state_vector;
    case CdmSectionId::kCovariance: return covariance;
    default: return metadata;
  }
}
bool CdmObject::operator==(const CdmObject& o) const {
  return metadata == o.metadata && od_parameters == o.od_parameters &&
         additional_parameters == o.additional_parameters && state_vector == o.state_vector &&
         covariance == o.covariance;
}
bool Cdm::operator==(const Cdm& o) const {
  return header == o.header && relative == o.relative && object[0] == o.object[0] &&
         object[1] == o.object[1];
}

std::string cdm_value(const CdmSection& s, const std::string& key) {
  const CdmItem* it = s.find(key);
  return it ? it->value : std::string();
}

StateEci cdm_state(const Cdm& c, int i) {
  const CdmSection& s = c.object[i].state_vector;
  auto v = [&](const char* k) { return std::strtod(cdm_value(s, k).c_str(), nullptr) * 1e3; };
  return {Vec3(v("X"), v("Y"), v("Z")), Vec3(v("X_DOT"), v("Y_DOT"), v("Z_DOT"))};
}

Mat6 cdm_cov_rtn(const Cdm& c, int i) {
  Mat6 m;
  const std::vector<std::string>& keys = internal::covariance_keyword_table();
  for (int r = 0; r < 6; ++r) {
    for (int k = 0; k <= r; ++k) {
      m(r, k) = m(k, r) =
          std::strtod(cdm_value(c.object[i].covariance, keys[r * (r + 1) / 2 + k]).c_str(), nullptr);
    }
  }
  return m;
}

std::vector<int> cdm_cov_rows(const Cdm& c, int i) {
  std::vector<int> rows = {0, 1, 2, 3, 4, 5};
  const std::vector<std::string>& keys = internal::covariance_keyword_table();
  for (int r = 6; r < 9; ++r) {  // CDRG, CSRP, CTHR: present when their diagonal term is
    if (c.object[i].covariance.find(keys[r * (r + 1) / 2 + r]) != nullptr) rows.push_back(r);
  }
  return rows;
}

Eigen::MatrixXd cdm_cov_rtn_full(const Cdm& c, int i) {
  const std::vector<int> rows = cdm_cov_rows(c, i);
  const std::vector<std::string>& keys = internal::covariance_keyword_table();
  const int n = static_cast<int>(rows.size());
  Eigen::MatrixXd m(n, n);
  for (int a = 0; a < n; ++a) {
    for (int b = 0; b <= a; ++b) {
      const int r = rows[static_cast<std::size_t>(a)], k = rows[static_cast<std::size_t>(b)];
      const std::string v = cdm_value(c.object[i].covariance, keys[r * (r + 1) / 2 + k]);
      m(a, b) = m(b, a) = std::strtod(v.c_str(), nullptr);  // absent off-diagonal: 0
    }
  }
  return m;
}

std::vector<std::string> cdm_covariance_notes(const Cdm& c) {
  static const char* const kRowNames[9] = {"R", "T", "N", "RDOT", "TDOT", "NDOT", "DRG", "SRP",
                                           "THR"};
  std::vector<std::string> notes;
  for (int i = 0; i < 2; ++i) {
    const std::vector<int> rows = cdm_cov_rows(c, i);
    if (rows.size() <= 6) continue;  // the 6x6 is checked (and repaired) by the assessment
    const Eigen::MatrixXd m = cdm_cov_rtn_full(c, i);
    // Scaled to unit diagonal, so rows of different units compare: the correlation matrix.
    const Eigen::VectorXd d = m.diagonal().cwiseMax(1e-300).cwiseSqrt().cwiseInverse();
    const Eigen::MatrixXd corr = d.asDiagonal() * m * d.asDiagonal();
    const double min_ev = Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(corr).eigenvalues().minCoeff();
    const double min_ev6 =  // an NPD 6x6 block is the assessment's repair, reported there
        Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd>(corr.topLeftCorner(6, 6)).eigenvalues().minCoeff();
    if (min_ev > 0.0 || min_ev6 <= 0.0) continue;
    std::string names;
    for (const int r : rows) names += std::string(names.empty() ? "" : ",") + kRowNames[r];
    char b[96];
    (void)std::snprintf(b, sizeof b, "%.3e", min_ev);
    notes.push_back("object " + std::to_string(i + 1) + "'s " + std::to_string(rows.size()) + "x" +
                    std::to_string(rows.size()) + " covariance (" + names +
                    ") is not positive definite (smallest eigenvalue of its correlation matrix " +
                    b + "); the Pc uses the 6x6 position-velocity block, checked on its own");
  }
  return notes;
}

}  // namespace evade::ccsds
