// Scenario reader of the conjunction screening (see screen_scenario.hpp).
#include "evade/commands/screen_scenario.hpp"

#include <stdexcept>

#include "evade/config/read_params.hpp"
#include "evade/core/epoch.hpp"

namespace evade::commands {
namespace {

const Param<ScreenScenario> kScreenScenarioRows[] = {
    with_flag(EVADE_PARAM_REAL(ScreenScenario, span_s, "s", 1e-3, 1e8, false,
                               "screened span from the epoch"),
              "--span-s"),
};

}  // namespace

ParamTable<ScreenScenario> screen_scenario_params() noexcept {
  return make_param_table(kScreenScenarioRows);
}

ScreenScenario read_screen_scenario(const config::Scenario& sc) {
  ScreenScenario in;
  in.earth = config::read_earth(sc);
  in.epoch_utc = sc.get_string("epoch_utc", in.epoch_utc);
  in.epoch_j2000_s = seconds_since_j2000_from_calendar(parse_calendar_utc(in.epoch_utc));
  config::require_params(sc, "", screen_scenario_params(), in);
  config::read_params(sc, "", screen_scenario_params(), &in);
  in.gravity = sc.get_enum("gravity", {"two_body", "two_body_j2"}, "two_body") == "two_body_j2"
                   ? GravityModel::kTwoBodyJ2
                   : GravityModel::kTwoBody;
  config::read_params(sc, "paper_step.", conjunction::paper_step_params(), &in.paper_step);
  config::read_params(sc, "robust.", conjunction::screen_options_params(), &in.robust);
  in.robust.warning_multiple = in.paper_step.n_warning;
  in.robust.gravity = in.gravity;
  in.robust.earth = in.earth;
  try {
    in.paper_step.validate();
    in.robust.validate();
  } catch (const std::invalid_argument& e) {
    throw config::ConfigError(sc.source() + ": " + e.what());
  }
  return in;
}

}  // namespace evade::commands
