// `evade assess`: collision probability of one conjunction (issue 12). The encounter comes
// from a scenario's `conjunction:` block (--scenario), a CCSDS CDM (--cdm, KVN or XML) or the
// encounter plane directly (--encounter-plane MISS_X_M,MISS_Y_M,SIGMA_X_M,SIGMA_Y_M,HBR_M).
// Parses, calls evade::commands::run_assess (assess_command.hpp) and prints; --json prints
// miss_m, rel_speed_mps, pc_2d, pc_chan, pc_max (and pc_mc, pc_mc_low, pc_mc_high with --mc N
// --seed S), the encounter plane used, how the states were brought to TCA and the short-term
// validity verdict; with --cdm also the message's own TCA, MISS_DISTANCE, RELATIVE_SPEED and
// COLLISION_PROBABILITY.
#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "cli.hpp"
#include "number_list.hpp"
#include "param_flag_option.hpp"
#include "evade/config/read_params.hpp"
#include "evade/commands/assess_command.hpp"
#include "evade/distributed/distributed_pc_monte_carlo.hpp"
#include "evade/distributed/mpi_session.hpp"

namespace evade::cli {
namespace {
namespace cmd_assess {  // a name of its own: the CLI builds as unity batches too

using namespace evade::assessment;
using namespace evade::commands;

struct Options {
  CommonOptions common;  // --scenario, --set, --json
  std::vector<ParamValue> params;  // --window-s, typed (evade/config/param_flags.hpp)
  std::string cdm, plane;
  double hbr_m = 0.0;
  long mc = 0;
  std::uint64_t seed = 1;
  int threads = 0;  // 0: all cores
};

AssessRequest plane_request(const std::string& plane) {
  const std::vector<double> v = parse_number_list(plane, ',');
  if (v.size() != 5) {
    throw std::invalid_argument("--encounter-plane: expected MISS_X_M,MISS_Y_M,SIGMA_X_M,"
                                "SIGMA_Y_M,HBR_M, found '" + plane + "'");
  }
  return encounter_plane_request(PrincipalEncounter{v[0], v[1], v[2], v[3]}, v[4]);
}

AssessRequest states_request(const Options& o) {
  config::Scenario sc =
      o.common.scenario.empty() ? config::Scenario::empty("--cdm") : load_scenario(o.common);
  if (o.common.scenario.empty()) {
    for (const auto& a : o.common.sets) sc.apply_override(a);
  }
  for (const ParamValue& v : o.params) sc.set_value(v);
  if (!o.common.scenario.empty()) return read_assess_request(sc);
  return read_assess_request_cdm(sc, read_text_file(o.cdm, "--cdm"), o.cdm, o.hbr_m);
}

int run(const Options& o) {
  const int sources = !o.common.scenario.empty() + !o.cdm.empty() + !o.plane.empty();
  if (sources != 1)
    throw std::invalid_argument("give exactly one of --scenario, --cdm, --encounter-plane");
  if (!o.plane.empty() && (!o.common.sets.empty() || !o.params.empty())) {
    throw std::invalid_argument("--set and --window-s do not apply to --encounter-plane (no "
                                "states: the 2D Pc only)");
  }
  AssessRequest req = o.plane.empty() ? states_request(o) : plane_request(o.plane);
  req.mc_samples = o.mc;
  req.mc_seed = o.seed;
  const distributed::MpiSession mpi;  // one process unless started by mpirun
  req.mc_exec = distributed::mpi_mc_execution(
      o.threads > 0 ? o.threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency())),
      mpi);
  const AssessResult r = run_assess(req);
  if (mpi.rank() != 0) return 0;  // every rank holds the result; rank 0 prints it
  // Every repair and every reading note on stderr as well as in the JSON and the text output:
  // a result computed from a repaired covariance must never look like one from the input.
  for (const std::string& w : assess_warnings(r))
    (void)std::fprintf(stderr, "evade assess: %s\n", w.c_str());
  if (o.common.json) print_json(to_json(r));
  else std::printf("%s", to_text(r).c_str());
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--scenario", o->common.scenario, "scenario with a conjunction: block");
  app.add_option("--cdm", o->cdm, "a CCSDS CDM file (KVN or XML)");
  app.add_option("--encounter-plane", o->plane, "MISS_X_M,MISS_Y_M,SIGMA_X_M,SIGMA_Y_M,HBR_M [m]");
  app.add_option("--set", o->common.sets, "override a scenario key (repeatable)");
  app.add_option("--hbr-m", o->hbr_m, "hard-body radius for --cdm [m]")->check(CLI::PositiveNumber);
  app.add_option("--mc", o->mc, "Monte Carlo samples [-]")->check(CLI::Range(1L, 100000000L));
  app.add_option("--seed", o->seed, "Monte Carlo seed [-]")->capture_default_str();
  app.add_option("--threads", o->threads, "Monte Carlo worker threads [-] (default: all cores)")
      ->check(CLI::Range(1, 256));
  (void)add_param_flag(app, assess_params(), "assessment.", "assessment.window_s", &o->params);
  app.add_flag("--json", o->common.json, "print a machine-readable JSON result on stdout");
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"assess"},
     "Collision probability of one conjunction (2D, Chan, max, 3D-Nc, Monte Carlo; the "
     "recommended Pc and its method)",
     &setup});

}  // namespace cmd_assess
}  // namespace
}  // namespace evade::cli
