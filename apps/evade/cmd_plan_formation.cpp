// `evade plan formation`: paper 003 (Duan et al.) — formation-constellation collision
// avoidance by a small semi-major-axis change. Prints the drift coefficients K_Ω, K_φ,
// K_am (paper eqs. 2, 4), Table 1 (limits per constraint and overall), the decision
// (direction, Δa, burn times, vis-viva Δv) and its verification by two-body + J2
// propagation (miss at the TCA, each constraint's minimum margin over T days).
// --numerical-limits adds Table 1 recomputed by bisection on propagated margins. --publish
// sends the decision's two burns (formation::make_burn_plan) as evade_burn_plan_t on LCM
// (plan_output.hpp, the same path as the other planners). I/O only: everything is read,
// computed and formatted by commands::read_formation_request, run_formation, to_json and
// to_text (src/commands/); this file parses the flags and prints.
#include <cstdio>
#include <iostream>
#include <memory>
#include <string>

#include "cli.hpp"
#include "evade/commands/formation_command.hpp"
#include "plan_output.hpp"

namespace evade::cli {
namespace {
namespace cmd_plan_formation {  // a name of its own: the CLI builds as unity batches too

using namespace evade::formation;
using namespace evade::commands;

struct PlanFormationOptions {
  CommonOptions common;
  bool numerical_limits = false;
  PlanOutputOptions out;
};

int run_command(const PlanFormationOptions& o) {
  FormationRequest req = read_formation_request(load_scenario(o.common));
  req.numerical_limits = o.numerical_limits;
  req.progress = [](const std::string& line) { std::cerr << line << "\n"; };
  const FormationResult r = run_formation(req);
  nlohmann::json j = to_json(r);
  const int uplink_rc =
      plan_wanted(o.out) ? output_plan(o.out, make_burn_plan(r, plan_id(o.out)), &j) : 0;
  print_result(o.common.json, j, to_text(r));
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<PlanFormationOptions>();
  add_common_options(app, o->common, "seed3");
  app.add_flag("--numerical-limits", o->numerical_limits,
               "also compute Table 1 by bisection on propagated margins (slower)");
  add_plan_output_options(app, o->out);
  return [o]() { return run_command(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "formation"},
     "Formation collision avoidance by a small semi-major-axis change (paper 003)",
     &setup});

}  // namespace cmd_plan_formation
}  // namespace
}  // namespace evade::cli
