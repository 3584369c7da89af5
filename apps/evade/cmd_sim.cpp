// `evade sim`: closed-loop close-range evasion simulation (paper 000, Yao & Wang 2012, sec. 4
// and Table 2). The command parses its flags, calls evade::sim (run_sim_command, or
// run_sim_plan with --plan), with the guidance in evade_guidance_node over LCM through
// lcm_link::sim_lcm_guidance (--lcm-url URL) and the Monte Carlo over MPI ranks through
// distributed::run_monte_carlo_campaign (--runs under mpirun), writes the time history the
// user asked for (--csv, --plot) and prints the result's JSON or text.
//
//   evade sim --scenario seed0 --accel 1 --detect 10 --json
//   evade sim --scenario seed0 --noise-rad 50e-6 --no-rates --runs 200 --seed 7 --json
//   evade sim --scenario seed0 --csv run.csv --plot run.png
//   evade sim --scenario seed0 --lcm-url URL --realtime --json   (node at its own fixed rate)
//   evade sim --plan plan.json --plan-epoch-s 10 --json       (a burn plan)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "cli.hpp"
#include "param_flag_option.hpp"
#include "run_program.hpp"
#include "evade/config/read_params.hpp"
#include "evade/distributed/distributed_monte_carlo.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/lcm_link/sim_lcm_guidance.hpp"
#include "evade/commands/sim_command.hpp"
#include "evade/commands/sim_csv.hpp"
#include "evade/commands/sim_overrides.hpp"
#include "evade/sim/sim_params.hpp"
#include "evade/commands/sim_plan_command.hpp"

namespace {
namespace cmd_sim {  // a name of its own: the CLI builds as unity batches too

using namespace evade;

struct SimOptions {
  cli::CommonOptions common;
  /// The parameter flags given, typed (evade/config/param_flags.hpp).
  std::vector<ParamValue> param_values;
  bool no_rates = false;
  int runs = 0;
  long long seed = 1;
  int threads = 2;
  std::string csv;
  std::string plot;
  std::string lcm_url;
  bool lockstep = true;
  double lcm_timeout_s = 5.0;
  bool realtime = false;
  std::string key_file;  ///< --key: sign nav, angles and the sim clock with this sensor key
  int key_id = 0;
  std::string plan_file;     ///< --plan: fly this burn-plan file
  double plan_epoch_s = 0.0;  ///< the plan's t = 0, seconds after the run starts
  double plan_after_s = 0.0;  ///< extra run time after the last burn [s]
};

std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}

// The scenario with the parameter flags' values given to it typed (then the sensor rule:
// sim_overrides.hpp).
config::Scenario scenario_with_flags(const SimOptions& o) {
  config::Scenario sc = cli::load_scenario(o.common);
  commands::apply_sim_overrides({o.param_values, o.no_rates}, &sc);
  return sc;
}

void check_plan_options(const SimOptions& o) {
  if (!o.plan_file.empty() &&
      (!o.lcm_url.empty() || o.runs > 0 || !o.csv.empty() || !o.plot.empty())) {
    throw std::invalid_argument("--plan runs the plan in process and cannot be combined with "
                                "--lcm-url, --runs, --csv or --plot (to fly a plan on the node, "
                                "publish it with `evade plan ... --publish`)");
  }
}

void check_lcm_options(const SimOptions& o) {
  if (!std::isfinite(o.lcm_timeout_s) || !(o.lcm_timeout_s > 0.0) || o.lcm_timeout_s > 3600.0) {
    throw std::invalid_argument("--lcm-timeout-s = " + num(o.lcm_timeout_s) +
                                " outside (0, 3600]");
  }
  if (o.realtime && o.lcm_url.empty()) {
    throw std::invalid_argument("--realtime needs --lcm-url URL (a node running at its own rate)");
  }
  if (o.realtime && o.runs > 0) throw std::invalid_argument("--runs cannot be combined with --realtime");
  if (!o.key_file.empty() && o.lcm_url.empty()) {
    throw std::invalid_argument("--key needs --lcm-url URL (it signs the messages sent to the node)");
  }
  if (o.runs > 0 && !o.lcm_url.empty()) {
    throw std::invalid_argument("--runs cannot be combined with --lcm-url");
  }
}

void check_run_options(const SimOptions& o) {
  check_plan_options(o);
  if (o.runs < 0 || o.runs > 1000000) {
    throw std::invalid_argument("--runs = " + std::to_string(o.runs) + " outside [0, 1000000]");
  }
  if (o.threads < 1 || o.threads > 64) {
    throw std::invalid_argument("--threads = " + std::to_string(o.threads) + " outside [1, 64]");
  }
  if (o.seed < 0) throw std::invalid_argument("--seed = " + std::to_string(o.seed) + " < 0");
  check_lcm_options(o);
}

// The time history's file: --csv, or with --plot alone PNG.csv beside the plot.
std::string csv_file(const SimOptions& o) {
  if (!o.csv.empty()) return o.csv;
  return o.plot.empty() ? std::string() : o.plot + ".csv";
}

// --csv: the file opened with its header (closed when csv goes out of scope).
sim::SampleCallback csv_writer(const SimOptions& o, std::ofstream& csv) {
  const std::string path = csv_file(o);
  if (path.empty()) return {};
  csv.open(path);
  if (!csv) {
    throw std::invalid_argument((o.csv.empty() ? "--plot: the time history " : "--csv = ") + path +
                                ": cannot open for writing");
  }
  csv << commands::sim_csv_header() << '\n';
  return [&csv](const sim::SimSample& s) { commands::write_sim_csv_row(csv, s); };
}

// --runs: progress on stderr; under `mpirun -np N` the runs are split between the ranks.
void set_monte_carlo(const SimOptions& o, commands::SimCommandRequest* req) {
  req->runs = o.runs;
  req->seed = static_cast<std::uint64_t>(o.seed);
  req->threads = o.threads;
  req->monte_carlo = &distributed::run_monte_carlo_campaign;
  auto mu = std::make_shared<std::mutex>();
  req->on_progress = [mu](int done, int total) {
    std::lock_guard<std::mutex> lock(*mu);
    if (done == total || done % std::max(1, total / 20) == 0) {
      (void)std::fprintf(stderr, "evade sim: monte carlo %d/%d\n", done, total);
    }
  };
}

// --lcm-url URL [--realtime] [--key FILE]: the guidance in evade_guidance_node.
void set_guidance(const SimOptions& o, commands::SimCommandRequest* req) {
  if (o.lcm_url.empty()) return;
  req->guidance = lcm_link::sim_lcm_guidance(
      {o.lcm_url, o.lockstep, o.lcm_timeout_s, o.realtime, o.key_file, o.key_id});
}

// --plot: scripts/plot_sim.py draws the CSV (its stdout to stderr). Returns false (message on
// stderr) on failure.
bool draw_plot(const SimOptions& o) {
  const std::vector<std::string> argv = {cli::python_interpreter(), cli::plot_script("plot_sim.py"),
                                         csv_file(o), o.plot};
  if (cli::run_program(argv, true) != 0) {
    (void)std::fprintf(stderr, "evade sim: plot failed (%s)\n", cli::command_line(argv).c_str());
    return false;
  }
  return true;
}

void print_warnings(const std::vector<std::string>& warnings) {
  for (const std::string& w : warnings) (void)std::fprintf(stderr, "evade sim: %s\n", w.c_str());
}

// --plan: the plan file flown by the in-process law + executor on the scenario's objects.
int run_plan(const SimOptions& o, const config::Scenario& sc) {
  commands::SimPlanRequest req = commands::read_sim_plan_request(sc);
  req.plan_file = o.plan_file;
  req.plan_epoch_s = o.plan_epoch_s;
  req.after_s = o.plan_after_s;
  const commands::SimPlanResult r = commands::run_sim_plan(req);
  print_warnings(r.warnings);
  cli::print_result(o.common.json, commands::to_json(r), commands::to_text(r));
  return r.all_delivered ? 0 : 1;
}

// The run, its time history written to --csv when given (the file closed on return).
commands::SimCommandResult simulate(const SimOptions& o, commands::SimCommandRequest req) {
  std::ofstream csv;
  req.on_sample = csv_writer(o, csv);
  return commands::run_sim_command(req);
}

int run_sim(const SimOptions& o) {
  const config::Scenario sc = scenario_with_flags(o);
  check_run_options(o);
  if (!o.plan_file.empty()) return run_plan(o, sc);
  commands::SimCommandRequest req = commands::read_sim_command_request(sc);
  set_monte_carlo(o, &req);
  set_guidance(o, &req);
  const commands::SimCommandResult r = simulate(o, std::move(req));
  print_warnings(r.warnings);
  if (!r.run.closest_approach_found) return 1;
  if (!r.reporting) return 0;  // MPI rank > 0: rank 0 prints
  if (!o.plot.empty() && !draw_plot(o)) return 1;
  cli::print_result(o.common.json, commands::to_json(r), commands::to_text(r));
  return 0;
}

// The parameter flags (evade/config/param_flags.hpp), each declared with its key's row; a
// given value reaches the scenario reader typed. sim's old --rate-hz (the sensor rate) is
// refused.
void add_parameter_flags(CLI::App& app, SimOptions& o) {
  std::size_t n_retired = 0;
  const config::RetiredFlag* retired = config::sim_retired_flags(&n_retired);
  cli::add_retired_flags(app, retired, n_retired);
  const auto add = [&](const auto& table, const char* prefix, const char* key) {
    return cli::add_param_flag(app, table, prefix, key, &o.param_values);
  };
  add(guidance::guidance_params(), "guidance.", "guidance.max_accel_mps2");
  add(sim::sim_params(), "", "encounter.detect_before_tca_s");
  CLI::Option* noise = add(sim::sim_params(), "", "sensor.noise_rad");
  noise->description(noise->get_description() +
                     " (given alone it selects the angles-only sensor; with --rate-noise-radps "
                     "the measured rates are kept)");
  add(sim::sim_params(), "", "sensor.rate_hz");
  add(guidance::guidance_params(), "guidance.", "guidance.rate_hz");
  add(sim::sim_params(), "", "sensor.rate_noise_radps");
  app.add_flag("--no-rates", o.no_rates, "angles only (the filter estimates the rates)");
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<SimOptions>();
  evade::cli::add_common_options(app, o->common, "seed0");
  add_parameter_flags(app, *o);
  app.add_option("--runs", o->runs, "Monte Carlo runs [-] (adds miss_m_p5/p50/p95)");
  app.add_option("--seed", o->seed, "Monte Carlo seed [-]");
  app.add_option("--threads", o->threads, "Monte Carlo threads [-]")->capture_default_str();
  app.add_option("--csv", o->csv, "write the time history (truth, estimates, commands)");
  app.add_option("--plot", o->plot,
                 "draw the time history into this PNG (scripts/plot_sim.py; the CSV is --csv, "
                 "or PNG.csv beside it)");
  app.add_option("--lcm-url,--lcm", o->lcm_url,
                 "run the guidance in evade_guidance_node over LCM at this URL (--lcm: the old "
                 "spelling, kept as an alias)");
  app.add_option("--lcm-lockstep", o->lockstep, "wait for the node's command every cycle")
      ->capture_default_str();
  app.add_option("--lcm-timeout-s", o->lcm_timeout_s, "LCM reply timeout [s]")
      ->capture_default_str();
  app.add_flag("--realtime", o->realtime,
               "with --lcm-url: truth at wall-clock pace, the node at its own fixed rate "
               "(no lockstep); adds command_age_ms_* and sim_late_steps");
  app.add_option("--key", o->key_file,
                 "with --lcm-url: sign nav, angles and the sim clock with this sensor key file "
                 "(`evade keygen --role sensor`; docs/SECURITY.md)");
  app.add_option("--key-id", o->key_id, "which sensor key of --key [-] (default: its only one)")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--plan", o->plan_file,
                 "fly this burn-plan file (`evade plan ... --plan-out`) with the in-process "
                 "law + plan executor on the scenario's objects");
  app.add_option("--plan-epoch-s", o->plan_epoch_s,
                 "with --plan: the plan's t = 0 this long after the run starts [s]")
      ->capture_default_str();
  app.add_option("--plan-after-s", o->plan_after_s,
                 "with --plan: run this long after the last burn [s]")
      ->capture_default_str();
  return [o]() { return run_sim(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"sim"}, "Closed-loop close-range evasion simulation (paper 000)", &setup});

}  // namespace cmd_sim
}  // namespace
