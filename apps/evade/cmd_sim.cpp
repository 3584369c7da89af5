// `evade sim`: closed-loop close-range evasion simulation (paper 000, Yao & Wang 2012, sec. 4
// and Table 2). Truth two-body + J2, sensor/actuator models and the guidance law behind a
// GuidanceEndpoint: in-process by default, or evade_guidance_node over LCM with --lcm URL.
// The command parses its flags, calls evade::sim (apply_sim_overrides, read_sim_config,
// run_simulation, run_monte_carlo, write_sim_csv_row) and prints.
//
//   evade sim --scenario seed0 --accel 1 --detect 10 --json
//   evade sim --scenario seed0 --noise-rad 50e-6 --no-rates --runs 200 --seed 7 --json
//   evade sim --scenario seed0 --csv run.csv --plot run.png
//   evade sim --scenario seed0 --lcm URL --realtime --json   (node at its own fixed rate)
//   evade sim --plan plan.json --plan-epoch-s 10 --json       (a burn plan, sim_plan.hpp)
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <memory>
#include <mutex>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "run_program.hpp"
#include "sim_plan.hpp"
#include "evade/distributed/distributed_monte_carlo.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/lcm_link/realtime_lcm_link.hpp"
#include "evade/lcm_link/sim_lcm_endpoint.hpp"
#include "evade/sim/monte_carlo.hpp"
#include "evade/sim/realtime_simulator.hpp"
#include "evade/sim/sim_csv.hpp"
#include "evade/sim/sim_overrides.hpp"
#include "evade/sim/simulator.hpp"

namespace {

using namespace evade;

struct SimOptions {
  cli::CommonOptions common;
  // Numeric flags are kept as text (empty = not given) and parsed here, so that "nan" or
  // "inf" is reported with the flag's name instead of silently meaning "not given".
  std::string accel_mps2;
  std::string detect_s;
  std::string noise_rad;
  std::string rate_hz;
  std::string guidance_hz;
  std::string rate_noise_radps;
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
  evade::cli::SimPlanOptions plan;
};

std::string num(double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return os.str();
}

// A flag given on the command line becomes a scenario override (sim::apply_sim_overrides), so
// its range is checked with the same rules as the file and it is echoed in "scenario_used".
// NaN/Inf or text that is not a number: exit 2 naming the flag and the key.
std::optional<double> number_flag(const char* flag, const char* key, const std::string& text) {
  if (text.empty()) return std::nullopt;
  double v = NAN;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v)) {
    throw std::invalid_argument(std::string(flag) + " = '" + text + "' (scenario key " + key +
                                "): must be a finite number");
  }
  return v;
}

sim::SimOverrides parse_overrides(const SimOptions& o) {
  sim::SimOverrides ov;
  ov.max_accel_mps2 = number_flag("--accel", "guidance.max_accel_mps2", o.accel_mps2);
  ov.detect_before_tca_s = number_flag("--detect", "encounter.detect_before_tca_s", o.detect_s);
  ov.noise_rad = number_flag("--noise-rad", "sensor.noise_rad", o.noise_rad);
  ov.sensor_rate_hz = number_flag("--rate-hz", "sensor.rate_hz", o.rate_hz);
  ov.guidance_rate_hz = number_flag("--guidance-hz", "guidance.rate_hz", o.guidance_hz);
  ov.rate_noise_radps =
      number_flag("--rate-noise-radps", "sensor.rate_noise_radps", o.rate_noise_radps);
  ov.no_rates = o.no_rates;
  return ov;
}

void check_plan_options(const SimOptions& o) {
  if (!o.plan.plan_file.empty() &&
      (!o.lcm_url.empty() || o.runs > 0 || !o.csv.empty() || !o.plot.empty())) {
    throw std::invalid_argument("--plan runs the plan in process and cannot be combined with "
                                "--lcm, --runs, --csv or --plot (to fly a plan on the node, "
                                "publish it with `evade plan ... --publish`)");
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
  if (!std::isfinite(o.lcm_timeout_s) || !(o.lcm_timeout_s > 0.0) || o.lcm_timeout_s > 3600.0) {
    throw std::invalid_argument("--lcm-timeout-s = " + num(o.lcm_timeout_s) +
                                " outside (0, 3600]");
  }
  if (o.realtime && o.lcm_url.empty()) {
    throw std::invalid_argument("--realtime needs --lcm URL (a node running at its own rate)");
  }
  if (o.realtime && o.runs > 0) throw std::invalid_argument("--runs cannot be combined with --realtime");
  if (!o.key_file.empty() && o.lcm_url.empty()) {
    throw std::invalid_argument("--key needs --lcm URL (it signs the messages sent to the node)");
  }
}

// --key: the sensor key that signs nav, angles and the sim clock (docs/SECURITY.md AUTH-3).
evade::guidance_lcm::SigningKey sensor_key(const SimOptions& o) {
  if (o.key_file.empty()) return {};
  return evade::lcm_link::load_signing_key(o.key_file, o.key_id, evade::auth::KeyRole::kSensor);
}

std::unique_ptr<sim::GuidanceEndpoint> make_endpoint(const SimOptions& o,
                                                     const sim::SimConfig& cfg) {
  if (!o.lcm_url.empty()) {
    return lcm_link::make_lcm_endpoint(o.lcm_url, o.lockstep, o.lcm_timeout_s, sensor_key(o));
  }
  return sim::make_in_process_endpoint(cfg.guidance, cfg.guidance.armed);
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
  csv << sim::sim_csv_header() << '\n';
  return [&csv](const sim::SimSample& s) { sim::write_sim_csv_row(csv, s); };
}

// One run (lockstep or in-process), its time history written to --csv when given.
sim::SimResult simulate(const SimOptions& o, const sim::SimConfig& cfg,
                        sim::GuidanceEndpoint& endpoint) {
  std::ofstream csv;
  return sim::run_simulation(cfg, endpoint, csv_writer(o, csv));
}

// --realtime: truth at wall-clock pace against a node at its own fixed rate.
sim::RealtimeResult simulate_realtime(const SimOptions& o, const sim::SimConfig& cfg) {
  const std::unique_ptr<sim::RealtimeLink> link = lcm_link::make_realtime_lcm_link(o.lcm_url, sensor_key(o));
  std::ofstream csv;
  sim::RealtimeResult r = sim::run_realtime_simulation(cfg, *link, csv_writer(o, csv));
  if (r.late_steps > 0) {
    (void)std::fprintf(stderr,
                       "evade sim: fell behind the wall clock in %ld of %ld steps (by more than "
                       "realtime.late_tolerance_s = %g s; worst %.3f ms); time was not slowed\n",
                       r.late_steps, r.steps, cfg.realtime.late_tolerance_s, r.late_max_ms);
  }
  return r;
}

void add_realtime(const sim::RealtimeResult& r, nlohmann::json* j) {
  (*j)["guidance"] = "lcm_realtime";
  (*j)["command_age_ms_p50"] = r.command_age_ms_p50;
  (*j)["command_age_ms_p99"] = r.command_age_ms_p99;
  (*j)["command_age_ms_max"] = r.command_age_ms_max;
  (*j)["commands_received"] = r.commands_received;
  (*j)["commands_discarded_old"] = r.commands_discarded_old;
  (*j)["commands_discarded_malformed"] = r.commands_discarded_malformed;
  (*j)["command_timeouts"] = r.command_timeouts;
  (*j)["sim_steps"] = r.steps;
  (*j)["sim_late_steps"] = r.late_steps;
  (*j)["sim_late_max_ms"] = r.late_max_ms;
  (*j)["start_utime_us"] = r.start_utime_us;
}

nlohmann::json result_json(const SimOptions& o, const sim::SimResult& r,
                           const sim::SimConfig& cfg, const config::Scenario& sc) {
  nlohmann::json j;
  j["miss_m"] = r.miss_m;
  j["tca_s"] = r.tca_s;
  j["dv_mps"] = r.dv_mps;
  j["burn_s"] = r.burn_s;
  j["cycles"] = r.cycles;
  j["start_s"] = r.start_s;
  j["nominal_tca_s"] = r.nominal_tca_s;
  j["nominal_miss_m"] = r.nominal_miss_m;
  j["measurements"] = r.measurements;
  j["dropouts"] = r.dropouts;
  j["guidance"] = o.lcm_url.empty() ? "in_process" : "lcm";
  if (!o.lcm_url.empty()) j["sensors_signed"] = !o.key_file.empty();
  if (r.has_final_status) {
    j["final_mode"] = guidance::mode_name(r.final_status.mode);
    j["final_reason"] = guidance::reason_name(r.final_status.reason);
    j["guidance_dv_used_mps"] = r.final_status.dv_used_mps;
    j["meas_accepted"] = r.final_status.meas_accepted;
    j["meas_rejected"] = r.final_status.meas_rejected;
    j["filter_reinits"] = r.final_status.filter_reinits;
  }
  j["parameters"] = {{"accel_mps2", cfg.guidance.max_accel_mps2},
                     {"detect_before_tca_s", cfg.encounter.detect_before_tca_s},
                     {"noise_rad", cfg.sensor.noise_rad},
                     {"sensor_rate_hz", cfg.sensor.rate_hz},
                     {"sensor_rates", cfg.sensor.has_rates},
                     {"rate_noise_radps", cfg.sensor.rate_noise_radps},
                     {"guidance_rate_hz", cfg.guidance.rate_hz},
                     {"gravity", cfg.gravity == GravityModel::kTwoBody ? "two_body"
                                                                      : "two_body_j2"},
                     {"scenario", sc.source()}};
  return j;
}

// --runs: the Monte Carlo over noise seeds (in-process guidance), progress on stderr. Under
// `mpirun -np N` the runs are split between the ranks; false on the ranks other than 0.
bool add_monte_carlo(const SimOptions& o, const sim::SimConfig& cfg, nlohmann::json* j) {
  if (!o.lcm_url.empty()) throw std::invalid_argument("--runs cannot be combined with --lcm");
  std::mutex mu;
  auto progress = [&mu](int done, int total) {
    std::lock_guard<std::mutex> lock(mu);
    if (done == total || done % std::max(1, total / 20) == 0) {
      (void)std::fprintf(stderr, "evade sim: monte carlo %d/%d\n", done, total);
    }
  };
  const distributed::MpiSession mpi;  // one process unless started by mpirun
  const sim::MonteCarloResult mc = distributed::run_monte_carlo_distributed(
      cfg, o.runs, static_cast<std::uint64_t>(o.seed), o.threads, mpi, progress);
  if (mpi.rank() != 0) return false;
  (*j)["runs"] = o.runs;
  (*j)["ranks"] = mpi.size();
  (*j)["seed"] = o.seed;
  (*j)["miss_m_min"] = mc.miss_min_m;
  (*j)["miss_m_p5"] = mc.miss_p5_m;
  (*j)["miss_m_p50"] = mc.miss_p50_m;
  (*j)["miss_m_p95"] = mc.miss_p95_m;
  (*j)["miss_m_max"] = mc.miss_max_m;
  (*j)["miss_m_mean"] = mc.miss_mean_m;
  return true;
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

void print_text(const SimOptions& o, const sim::SimResult& r, const nlohmann::json& j) {
  std::printf("miss %.4f m at tca %.6f s (nominal miss %.4f m); dv %.4f m/s, burn %.3f s, "
              "%ld cycles\n",
              r.miss_m, r.tca_s, r.nominal_miss_m, r.dv_mps, r.burn_s, r.cycles);
  if (o.runs > 0) {
    std::printf("monte carlo %d runs: miss p5 %.4f p50 %.4f p95 %.4f (min %.4f max %.4f) m\n",
                o.runs, j["miss_m_p5"].get<double>(), j["miss_m_p50"].get<double>(),
                j["miss_m_p95"].get<double>(), j["miss_m_min"].get<double>(),
                j["miss_m_max"].get<double>());
  }
}

// --plan: the plan file flown by the in-process law + executor on the scenario's objects.
int run_plan(const SimOptions& o, const config::Scenario& sc, const sim::SimConfig& cfg) {
  nlohmann::json j;
  const int rc = evade::cli::run_sim_plan(o.plan, cfg, &j);
  j["scenario"] = sc.source();
  j["scenario_used"] = sc.used();
  if (o.common.json) {
    cli::print_json(j);
  } else {
    evade::cli::print_sim_plan(j);
  }
  return rc;
}

int run_sim(const SimOptions& o) {
  config::Scenario sc = cli::load_scenario(o.common);
  sim::apply_sim_overrides(parse_overrides(o), &sc);
  check_run_options(o);
  const sim::SimConfig cfg = sim::read_sim_config(sc);
  if (!o.plan.plan_file.empty()) return run_plan(o, sc, cfg);

  std::optional<sim::RealtimeResult> rt;
  sim::SimResult r;
  if (o.realtime) {
    rt = simulate_realtime(o, cfg);
    r = rt->sim;
  } else {
    r = simulate(o, cfg, *make_endpoint(o, cfg));
  }
  if (!r.closest_approach_found) {
    (void)std::fprintf(stderr, "evade sim: no closest approach within %g s\n", cfg.encounter.max_duration_s);
    return 1;
  }
  nlohmann::json j = result_json(o, r, cfg, sc);
  if (rt) add_realtime(*rt, &j);
  if (o.runs > 0 && !add_monte_carlo(o, cfg, &j)) return 0;  // MPI rank > 0: rank 0 prints
  j["scenario_used"] = sc.used();
  if (!o.plot.empty() && !draw_plot(o)) return 1;

  if (o.common.json) {
    cli::print_json(j);
  } else {
    print_text(o, r, j);
  }
  return 0;
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<SimOptions>();
  evade::cli::add_common_options(app, o->common, "seed0");
  app.add_option("--accel", o->accel_mps2, "maximum acceleration [m/s^2] (guidance.max_accel_mps2)");
  app.add_option("--detect", o->detect_s,
                 "detection time before the nominal closest approach [s]");
  app.add_option("--noise-rad", o->noise_rad,
                 "angles-only sensor with this angle noise 1-sigma [rad] (keeps measured "
                 "rates only if --rate-noise-radps is also given)");
  app.add_option("--rate-hz", o->rate_hz, "sensor sample rate [Hz]");
  app.add_option("--guidance-hz", o->guidance_hz, "guidance cycle rate [Hz] (guidance.rate_hz)");
  app.add_option("--rate-noise-radps", o->rate_noise_radps,
                 "sensor angle-rate noise 1-sigma [rad/s]");
  app.add_flag("--no-rates", o->no_rates, "angles only (the filter estimates the rates)");
  app.add_option("--runs", o->runs, "Monte Carlo runs [-] (adds miss_m_p5/p50/p95)");
  app.add_option("--seed", o->seed, "Monte Carlo seed [-]");
  app.add_option("--threads", o->threads, "Monte Carlo threads [-]")->capture_default_str();
  app.add_option("--csv", o->csv, "write the time history (truth, estimates, commands)");
  app.add_option("--plot", o->plot,
                 "draw the time history into this PNG (scripts/plot_sim.py; the CSV is --csv, "
                 "or PNG.csv beside it)");
  app.add_option("--lcm", o->lcm_url,
                 "run the guidance in evade_guidance_node over LCM at this URL");
  app.add_option("--lcm-lockstep", o->lockstep, "wait for the node's command every cycle")
      ->capture_default_str();
  app.add_option("--lcm-timeout-s", o->lcm_timeout_s, "LCM reply timeout [s]")
      ->capture_default_str();
  app.add_flag("--realtime", o->realtime,
               "with --lcm: truth at wall-clock pace, the node at its own fixed rate "
               "(no lockstep); adds command_age_ms_* and sim_late_steps");
  app.add_option("--key", o->key_file,
                 "with --lcm: sign nav, angles and the sim clock with this sensor key file "
                 "(`evade keygen --role sensor`; docs/SECURITY.md)");
  app.add_option("--key-id", o->key_id, "which sensor key of --key [-] (default: its only one)")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--plan", o->plan.plan_file,
                 "fly this burn-plan file (`evade plan ... --plan-out`) with the in-process "
                 "law + plan executor on the scenario's objects");
  app.add_option("--plan-epoch-s", o->plan.epoch_s,
                 "with --plan: the plan's t = 0 this long after the run starts [s]")
      ->capture_default_str();
  app.add_option("--plan-after-s", o->plan.after_s,
                 "with --plan: run this long after the last burn [s]")
      ->capture_default_str();
  return [o]() { return run_sim(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"sim"}, "Closed-loop close-range evasion simulation (paper 000)", &setup});

}  // namespace
