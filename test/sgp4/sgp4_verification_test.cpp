// SGP4/SDP4 against the verification set of Vallado, Crawford, Hujsak & Kelso (2006),
// AIAA 2006-6753 (SGP4-VER.TLE: near-Earth, deep-space, resonant, Lyddane and error cases),
// with Debian's python3-sgp4 as the independent reference (test/sgp4/sgp4_reference.py
// writes its states before this test runs). Every epoch of every case in both operation
// modes must agree: the same error code, and where a state exists |dr| <= 1 mm and
// |dv| <= 1 um/s. The worst differences are printed and written to a table (--report).
//
// Usage: evade_sgp4_verification_test --tle SGP4-VER.TLE --ref REF.txt [--report OUT.md]
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace {

using evade::sgp4::OperationMode;

std::string g_tle, g_ref, g_report;

std::string read_text(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

struct RefRow {
  long catnum = 0;
  char mode = 'i';
  double t_min = 0.0;
  int error = 0;
  double r_km[3] = {0, 0, 0};
  double v_kmps[3] = {0, 0, 0};
};

std::vector<RefRow> read_reference(const std::string& path) {
  std::vector<RefRow> rows;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    RefRow r;
    std::string x[6];
    ls >> r.catnum >> r.mode >> r.t_min >> r.error >> x[0] >> x[1] >> x[2] >> x[3] >> x[4] >> x[5];
    if (!ls) continue;
    for (int i = 0; i < 3; ++i) {
      r.r_km[i] = std::strtod(x[i].c_str(), nullptr);
      r.v_kmps[i] = std::strtod(x[i + 3].c_str(), nullptr);
    }
    rows.push_back(r);
  }
  return rows;
}

struct CaseStats {
  int epochs = 0;
  double worst_dr_m = 0.0, worst_dv_mps = 0.0;
  int last_error = 0;
};

TEST(Sgp4Verification, EveryEpochMatchesPythonSgp4) {
  ASSERT_FALSE(g_tle.empty()) << "--tle not given";
  evade::sgp4::TleReadOptions opt;
  opt.check_checksum = false;      // three error cases of the published file carry bad ones
  opt.allow_trailing_text = true;  // start, stop and step minutes after column 69
  const evade::sgp4::Catalog cat = evade::sgp4::read_tle(read_text(g_tle), g_tle, opt);
  for (const auto& is : cat.issues) ADD_FAILURE() << is.message();
  ASSERT_GE(cat.objects.size(), 30u);
  std::map<long, evade::sgp4::MeanElements> by_id;
  for (const auto& m : cat.objects) by_id[m.norad_id] = m;
  const std::vector<RefRow> ref = read_reference(g_ref);
  ASSERT_GE(ref.size(), 1000u) << "reference file " << g_ref << " missing or short";
  std::map<std::pair<long, char>, CaseStats> stats;
  double worst_dr = 0.0, worst_dv = 0.0;
  std::string worst_dr_at, worst_dv_at;
  int compared = 0, error_epochs = 0;
  for (const RefRow& r : ref) {
    ASSERT_TRUE(by_id.count(r.catnum)) << r.catnum;
    const auto mode = r.mode == 'a' ? OperationMode::kAfspc : OperationMode::kImproved;
    const evade::sgp4::Sgp4Propagator prop(by_id.at(r.catnum), mode);
    const evade::sgp4::Sgp4State s = prop.propagate_min(r.t_min);
    const std::string at = std::to_string(r.catnum) + " '" + r.mode + "' t=" + std::to_string(r.t_min) + " min";
    ASSERT_EQ(static_cast<int>(s.error), r.error) << at;
    CaseStats& cs = stats[{r.catnum, r.mode}];
    cs.epochs++;
    cs.last_error = r.error;
    if (r.error != 0 && r.error != 6) {
      ++error_epochs;
      continue;
    }
    double dr2 = 0.0, dv2 = 0.0;
    for (int i = 0; i < 3; ++i) {
      dr2 += std::pow(s.r_teme_m[i] - r.r_km[i] * 1000.0, 2);
      dv2 += std::pow(s.v_teme_mps[i] - r.v_kmps[i] * 1000.0, 2);
    }
    const double dr = std::sqrt(dr2), dv = std::sqrt(dv2);
    EXPECT_LE(dr, 1e-3) << at;
    EXPECT_LE(dv, 1e-6) << at;
    cs.worst_dr_m = std::max(cs.worst_dr_m, dr);
    cs.worst_dv_mps = std::max(cs.worst_dv_mps, dv);
    if (dr > worst_dr) worst_dr = dr, worst_dr_at = at;
    if (dv > worst_dv) worst_dv = dv, worst_dv_at = at;
    ++compared;
  }
  std::printf("SGP4 verification: %zu cases x 2 modes, %d states compared, %d error epochs matched\n",
              cat.objects.size(), compared, error_epochs);
  std::printf("worst |dr| = %.3e m (%s)\nworst |dv| = %.3e m/s (%s)\n", worst_dr, worst_dr_at.c_str(),
              worst_dv, worst_dv_at.c_str());
  if (g_report.empty()) return;
  std::ofstream out(g_report);
  out << "| case | mode | epochs | ends with error | worst dr (m) | worst dv (m/s) |\n|---|---|---|---|---|---|\n";
  for (const auto& [key, cs] : stats) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "| %05ld | %c | %d | %d | %.2e | %.2e |\n", key.first, key.second, cs.epochs,
                  cs.last_error, cs.worst_dr_m, cs.worst_dv_mps);
    out << buf;
  }
  out << "\nworst |dr| = " << worst_dr << " m (" << worst_dr_at << "); worst |dv| = " << worst_dv << " m/s ("
      << worst_dv_at << "); " << compared << " states, " << error_epochs << " error epochs\n";
}

}  // namespace

int main(int argc, char** argv) {
  ::testing::InitGoogleTest(&argc, argv);
  for (int i = 1; i + 1 < argc; ++i) {
    const std::string a = argv[i];
    if (a == "--tle") g_tle = argv[++i];
    else if (a == "--ref") g_ref = argv[++i];
    else if (a == "--report") g_report = argv[++i];
  }
  return RUN_ALL_TESTS();
}
