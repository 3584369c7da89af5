// Reads the inputs of a conjunction screening (paper 002, Wang Xiaoyu 2006; issue 6) from a
// scenario, every number through a parameter table. Keys (SI units in their names):
//   epoch_utc                              (optional, "2000-01-01 12:00:00")
//   span_s                                 (required: screened span from the epoch)
//   gravity: two_body | two_body_j2        (optional, two_body)
//   earth.{mu_m3ps2, j2, re_m}             (optional, config::read_earth; WGS-84 default)
//   paper_step.{h_sim_s, n_warning, m_warning_period, l_enlarge, l_reduce}
//                                          (paper_step_params(), section 2 eq. 3-5)
//   robust.{threshold_m, step_s, leaf_s}   (screen_options_params())
// The objects (`objects` list, objects_from_scenario in catalog.hpp) are read separately:
// a command may take them from a CSV file or a synthetic population instead.
// Every violation throws config::ConfigError naming the key, the value and the range.
#pragma once

#include <string>

#include "evade/config/scenario.hpp"
#include "evade/conjunction/paper_step.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/core/param.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade::commands {

struct ScreenScenario {
  std::string epoch_utc = "2000-01-01 12:00:00";  ///< as written (echoed in results)
  double epoch_j2000_s = 0.0;   ///< epoch_utc in s since J2000
  double span_s = 0.0;          ///< screened span [s]; no default (required key)
  GravityModel gravity = GravityModel::kTwoBody;
  EarthModel earth = kEarthDefault;
  conjunction::PaperStepParams paper_step;   ///< validated
  /// robust.* read; gravity and earth as above, warning_multiple = paper_step.n_warning
  /// (the paper's N); threads and progress are left to the caller.
  conjunction::ScreenOptions robust;
};

/// The scenario's top-level number: span_s.
ParamTable<ScreenScenario> screen_scenario_params() noexcept;

/// Reads and validates everything above (does not read `objects`, does not call
/// check_all_used()).
ScreenScenario read_screen_scenario(const config::Scenario& sc);

}  // namespace evade::commands
