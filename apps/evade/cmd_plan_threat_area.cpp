// `evade plan threat-area`: paper 001 (Yu, Wang, Sun 2017) — the chaser's potential threat area
// (sec. 2.2), the target's optimal evasive burn direction at fixed V_E (sec. 3, GA → ISRES),
// the smallest eliminating burn (sec. 4.2, Fig. 8 / Table 3), and the transfer-time study
// (Fig. 4). I/O only: the request is read by commands::read_threat_area_request, the study run
// by commands::run_threat_area and printed by its to_json / to_text (src/commands/); this file
// parses the flags, prints and plots.
// --publish sends the evasive burn at V_E (threat::make_burn_plan: one RSW impulse at t0) as
// evade_burn_plan_t on LCM (plan_output.hpp, the same path as the other planners).
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "run_program.hpp"
#include "evade/threat/burn_plan.hpp"
#include "param_flag_option.hpp"
#include "plan_output.hpp"
#include "evade/commands/threat_area_command.hpp"
#include "evade/threat/threat_params.hpp"
#include "evade/config/read_params.hpp"

namespace evade::cli {
namespace {
namespace cmd_plan_threat_area {  // a name of its own: the CLI builds as unity batches too

using namespace evade::threat;
using namespace evade::commands;

struct ThreatCmdOptions {
  CommonOptions common;
  std::vector<ParamValue> param_values;  ///< --dv-mps, --dt-transfer-s, --impulses (typed)
  unsigned seed = 0;
  bool eliminate = false;
  std::vector<double> sweep_dv;
  std::vector<double> sweep_transfer;
  std::string plot;
  PlanOutputOptions out;
  CLI::Option* seed_opt = nullptr;
};

// The parameter flags (evade/config/param_flags.hpp): each given value is a scenario
// override, checked against its key's declaration.
void add_parameter_flags(CLI::App& app, ThreatCmdOptions& o) {
  const auto add = [&](const auto& table, const char* key) {
    (void)add_param_flag(app, table, "", key, &o.param_values);  // registered on app
  };
  add(evasion_params(), "evasion.dv_mps");
  add(threat_option_params(), "transfer.dt_s");
  add(threat_option_params(), "transfer.impulses");
}

void progress_elim(double lo, double hi) {
  (void)std::fprintf(stderr, "  eliminating V_E in [%.3f, %.3f] m/s\n", lo, hi);
}

// Progress lines on stderr as each step finishes.
ThreatStudyProgress stderr_progress() {
  ThreatStudyProgress p;
  p.optimizing = [](double dv_mps, int evals) {
    (void)std::fprintf(stderr, "threat-area: optimizing the burn direction at V_E = %.3f m/s (<= %d evals)\n",
                       dv_mps, evals);
  };
  p.eliminating = [](double tol_mps) {
    (void)std::fprintf(stderr, "threat-area: bisection for the eliminating V_E (tol %.3f m/s)\n",
                       tol_mps);
  };
  p.bisection = progress_elim;
  p.burn_row = [](const BurnSweepRow& row) {
    const EvasionResult& q = row.evasion;
    (void)std::fprintf(stderr, "  V_E = %8.3f m/s: arc %9.2f s (%7.3f deg), alpha %.4f theta %.4f\n",
                       q.dv_mps, q.area.arc_s, q.area.arc_deg, q.alpha_rad, q.theta_rad);
  };
  p.transfer_row = [](const TransferStudyRow& r) {
    const std::string elim =
        r.elimination ? ", eliminating " + std::to_string(r.elimination->eliminating_dv_mps) + " m/s"
                      : "";
    (void)std::fprintf(stderr, "  dT = %7.1f s: J(t0) = %.3f m/s, bound %.3f m/s%s\n", r.dt_transfer_s,
                       r.j_t0_mps, r.t0_bound_mps, elim.c_str());
  };
  return p;
}

// Writes the JSON beside the PNG and runs scripts/plot_threat.py on it; false on failure.
bool write_plot(const std::string& png, const nlohmann::json& j) {
  const std::string tmp = png + ".json";
  std::ofstream(tmp) << j.dump(2) << "\n";
  const std::vector<std::string> argv = {python_interpreter(), plot_script("plot_threat.py"), tmp,
                                         png};
  if (run_program(argv, false) != 0) {
    (void)std::fprintf(stderr, "threat-area: plot failed: %s\n", command_line(argv).c_str());
    return false;
  }
  (void)std::fprintf(stderr, "threat-area: wrote %s (data %s)\n", png.c_str(), tmp.c_str());
  return true;
}

int run_command(const ThreatCmdOptions& o) {
  config::Scenario sc = load_scenario(o.common);
  for (const ParamValue& v : o.param_values) sc.set_value(v);
  ThreatAreaRequest req = read_threat_area_request(sc);
  if (o.seed_opt->count() > 0) req.scenario.evasion.seed = o.seed;
  req.study.eliminate = o.eliminate;
  req.study.sweep_dv_mps = o.sweep_dv;
  req.study.sweep_transfer_s = o.sweep_transfer;
  req.progress = stderr_progress();
  const ThreatAreaResult r = run_threat_area(req);
  nlohmann::json j = to_json(r);
  const int uplink_rc =
      plan_wanted(o.out) ? output_plan(o.out, make_burn_plan(r.study.evasion, plan_id(o.out)), &j) : 0;
  if (!o.plot.empty() && !write_plot(o.plot, j)) return 1;
  print_result(o.common.json, j, to_text(r));
  return uplink_rc;  // 0, or the uplink's 3 (rejected) / 4 (no acknowledgement)
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<ThreatCmdOptions>();
  add_common_options(app, o->common);
  add_parameter_flags(app, *o);
  o->seed_opt = app.add_option("--seed", o->seed, "seed: ISRES RNG / the sweep's sample position in each cell [-]");
  app.add_flag("--eliminate", o->eliminate, "find the smallest V_E with no threat area");
  app.add_option("--sweep-dv", o->sweep_dv, "list of V_E [m/s]: arc for each (Fig. 8)")
      ->delimiter(',');
  app.add_option("--sweep-transfer", o->sweep_transfer,
                 "list of transfer times [s] (Fig. 4; with --eliminate: eliminating V_E)")
      ->delimiter(',');
  app.add_option("--plot", o->plot, "PNG file for the sweep plots (scripts/plot_threat.py)");
  add_plan_output_options(app, o->out);
  return [o]() { return run_command(*o); };
}

const bool kRegistered = register_command(
    {{"plan", "threat-area"},
     "Threat-area evasive burn (paper 001): potential threat area, optimal direction, "
     "eliminating burn",
     &setup});

}  // namespace cmd_plan_threat_area
}  // namespace
}  // namespace evade::cli
