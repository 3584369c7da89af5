// `evade plan observability`: the observability-minimizing evasive burn of paper 004 (Yu,
// Wang, Zhou; eq. 23 and §3). Parse -> call -> print: the scenario is read, the burn planned
// and compared with the paper's directions by evade::observability (observability_command.hpp);
// this file keeps the flags, the progress lines on stderr and, with --publish / --plan-out,
// the plan (observability::make_burn_plan) sent as evade_burn_plan_t on LCM or written to a
// file (plan_output.hpp, shared by the planners); the library evade::observability stays
// LCM-free.
#include <cstdio>
#include <memory>
#include <string>

#include "cli.hpp"
#include "plan_output.hpp"
#include "evade/observability/burn_plan.hpp"
#include "evade/commands/observability_command.hpp"

namespace evade::cli {
namespace {
namespace cmd_plan_observability {  // a name of its own: the CLI builds as unity batches too

struct Options {
  CommonOptions common;
  commands::ObservabilityOverrides overrides;  // --objective, --seed
  PlanOutputOptions out;
};

int run(const Options& o) {
  const config::Scenario sc = load_scenario(o.common);
  commands::ObservabilityRequest req =
      commands::read_observability_request(sc, o.overrides);
  req.isres.progress = [](int n, double best) {
    (void)std::fprintf(stderr, "plan observability: %d evaluations, best %.9g\n", n, best);
  };
  const commands::ObservabilityResult r = commands::run_observability(req);
  (void)std::fprintf(stderr, "plan observability: done, %d evaluations in %.3f s\n",
                     r.plan.evaluations, r.runtime_s);

  nlohmann::json j = commands::to_json(r);
  const int uplink_rc =
      plan_wanted(o.out)
          ? output_plan(o.out, observability::make_burn_plan(r.plan, plan_id(o.out)), &j)
          : 0;
  print_result(o.common.json, j, commands::to_text(r));
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  add_common_options(app, o->common, "seed4");
  app.add_option("--objective", o->overrides.objective,
                 "paper | los-change | estimation (default: scenario)")
      ->check(CLI::IsMember({"paper", "los-change", "estimation"}));
  app.add_option("--seed", o->overrides.seed, "ISRES seed [-] (default: scenario isres.seed)")
      ->check(CLI::Range(0L, 2147483647L));
  add_plan_output_options(app, o->out);
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "observability"}, "Observability-minimizing evasive burn (paper 004)", &setup});

}  // namespace cmd_plan_observability
}  // namespace
}  // namespace evade::cli
