// Conjunction readers (include/evade/commands/conjunction_input.hpp).
#include "evade/commands/conjunction_input.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "evade/ccsds/cdm_formats.hpp"
#include "evade/assessment/covariance.hpp"
#include "evade/config/read_params.hpp"

namespace evade::commands {
namespace {

// A 3x3 or 6x6 nested list at key.
Mat6 read_matrix(const config::Scenario& sc, const std::string& key, bool* six) {
  const std::size_t n = sc.list_size(key);
  if (n != 3 && n != 6) {
    throw config::ConfigError(sc.source() + ": key '" + key +
                              "': expected a 3x3 or 6x6 nested list, found " +
                              std::to_string(n) + " rows");
  }
  Mat6 m = Mat6::Zero();
  for (std::size_t i = 0; i < n; ++i) {
    const std::string row = key + "." + std::to_string(i);
    const std::vector<double> v = sc.get_double_list(row, -1e20, 1e20, n);
    if (v.size() != n) {
      throw config::ConfigError(sc.source() + ": key '" + row + "': expected " +
                                std::to_string(n) + " numbers, found " + std::to_string(v.size()));
    }
    for (std::size_t j = 0; j < n; ++j) m(static_cast<int>(i), static_cast<int>(j)) = v[j];
  }
  *six = n == 6;
  return m;
}

assessment::ObjectState read_object(const config::Scenario& sc, const std::string& p, const std::string& name) {
  assessment::ObjectState o;
  o.name = name;
  o.state.r_eci_m = sc.get_vec3(p + ".r_eci_m", -1e9, 1e9);
  o.state.v_eci_mps = sc.get_vec3(p + ".v_eci_mps", -1e6, 1e6);
  const bool eci = sc.has(p + ".cov_eci_m2"), rtn = sc.has(p + ".cov_rtn_m2");
  if (eci == rtn) {
    throw config::ConfigError(sc.source() + ": key '" + p +
                              "': expected exactly one of cov_eci_m2 or cov_rtn_m2");
  }
  bool six = false;
  const Mat6 m = read_matrix(sc, p + (eci ? ".cov_eci_m2" : ".cov_rtn_m2"), &six);
  o.has_velocity_cov = six;
  o.cov_eci = eci ? m : assessment::cov_eci_from_rtn(m, o.state);
  return o;
}

}  // namespace

assessment::ConjunctionInput read_conjunction_scenario(const config::Scenario& sc) {
  assessment::ConjunctionInput in;
  in.hbr_m = sc.get_double("conjunction.hbr_m", 1e-3, 1e4);
  in.obj[0] = read_object(sc, "conjunction.object1", "object1");
  in.obj[1] = read_object(sc, "conjunction.object2", "object2");
  in.earth = config::read_earth(sc);
  return in;
}

assessment::ConjunctionInput conjunction_from_cdm(const ccsds::Cdm& cdm, double hbr_m, const EarthModel& earth) {
  assessment::ConjunctionInput in;
  in.earth = earth;
  in.hbr_m = hbr_m;
  if (hbr_m != 0.0 && !(std::isfinite(hbr_m) && hbr_m > 0.0)) {  // 0: not given
    throw std::invalid_argument("--hbr-m = " + std::to_string(hbr_m) +
                                ": the hard-body radius must be a finite number > 0 [m]");
  }
  if (hbr_m == 0.0) {
    const std::string a1 = ccsds::cdm_value(cdm.object[0].additional_parameters, "AREA_PC");
    const std::string a2 = ccsds::cdm_value(cdm.object[1].additional_parameters, "AREA_PC");
    if (a1.empty() || a2.empty()) {
      throw std::invalid_argument(
          "CDM: no hard-body radius: give --hbr-m, or AREA_PC for both objects");
    }
    in.hbr_m = std::sqrt(std::strtod(a1.c_str(), nullptr) / kPi) +
               std::sqrt(std::strtod(a2.c_str(), nullptr) / kPi);
  }
  for (int i = 0; i < 2; ++i) {
    const std::string frame = ccsds::cdm_value(cdm.object[i].metadata, "REF_FRAME");
    if (frame == "ITRF") {
      throw std::invalid_argument("CDM: REF_FRAME = ITRF is not supported (EME2000 or GCRF)");
    }
    in.obj[i].name = ccsds::cdm_value(cdm.object[i].metadata, "OBJECT_NAME");
    in.obj[i].state = ccsds::cdm_state(cdm, i);
    const Mat6 rtn = ccsds::cdm_cov_rtn(cdm, i);
    if (rtn.block<3, 3>(0, 0).isZero(0.0)) {  // how a CDM says "not known" (cdm_from_event.hpp)
      throw std::invalid_argument("CDM: object " + std::to_string(i + 1) + " (" + in.obj[i].name +
                                  "): the position covariance is all zero (not known): no Pc");
    }
    in.obj[i].cov_eci = assessment::cov_eci_from_rtn(rtn, in.obj[i].state);
    in.obj[i].has_velocity_cov = true;
  }
  return in;
}

}  // namespace evade::commands
