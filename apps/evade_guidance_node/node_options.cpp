// Options of evade_guidance_node: flags first, then the optional YAML overrides them
// key by key (design_node.md NODE-CFG-1). Every value is range-checked with its key named.
#include "node_options.hpp"

#include <sstream>
#include <stdexcept>

#include "evade/config/scenario.hpp"
#include "evade/sim/sim_scenario.hpp"

namespace evade::node {

void add_options(CLI::App& app, NodeOptions& o) {
  app.add_option("--lcm-url", o.lcm_url, "LCM provider URL (e.g. udpm://239.255.76.67:7667?ttl=0, "
                                          "memq://, file:///path.log?speed=0)");
  app.add_option("--out-lcm-url", o.out_lcm_url,
                 "publish command/status on this URL instead (e.g. file:///out.log?mode=w)");
  app.add_option("--rate-hz", o.rate_hz, "loop rate [Hz] (also the law's nominal cycle)")
      ->capture_default_str();
  app.add_flag("--lockstep", o.lockstep, "run one cycle per evade_sim_clock_t tick");
  app.add_flag("--realtime", o.realtime, "try SCHED_FIFO and mlockall (continues if refused)");
  app.add_option("--rt-priority", o.rt_priority, "SCHED_FIFO priority")->capture_default_str();
  app.add_option("--stale-ms", o.stale_ms, "input stale limit [ms]")->capture_default_str();
  app.add_option("--max-accel-mps2", o.max_accel_mps2, "maximum acceleration [m/s^2]")
      ->capture_default_str();
  app.add_option("--config", o.config, "optional YAML with guidance.* and node.* keys");
  app.add_option("--scenario", o.scenario,
                 "take the guidance parameters (guidance.*) from this sim scenario, exactly as "
                 "`evade sim` does (flags given explicitly still win)");
  app.add_option("--set", o.sets, "override a scenario key: --set key.path=value (repeatable)");
  app.add_option("--max-cycles", o.max_cycles, "stop after N cycles (0 = until SIGINT/SIGTERM)");
  app.add_option("--idle-exit-s", o.idle_exit_s,
                 "lockstep: exit after this long without a tick (0 = never)");
  app.add_flag("--start-disarmed", o.start_disarmed, "start disarmed (evade_arm_t arms)");
  app.add_option("--status-divider", o.status_divider, "publish status every N cycles")
      ->capture_default_str();
  app.add_option("--queue", o.queue_capacity, "bounded input queue capacity")
      ->capture_default_str();
  app.add_flag("--stats-json", o.stats_json, "print run statistics as JSON on stdout at exit");
  app.add_flag("--quiet", o.quiet, "no progress messages on stderr");
}

void note_given(const CLI::App& app, NodeOptions& o) {
  o.rate_given = app.count("--rate-hz") > 0;
  o.stale_given = app.count("--stale-ms") > 0;
  o.accel_given = app.count("--max-accel-mps2") > 0;
}

namespace {

void check(bool ok, const char* key, double value, const char* range) {
  if (ok) return;
  std::ostringstream os;
  os << key << " = " << value << " outside " << range;
  throw std::invalid_argument(os.str());
}

}  // namespace

guidance_lcm::NodeConfig make_node_config(const NodeOptions& o) {
  check(o.rate_hz > 0.0 && o.rate_hz <= 1000.0, "--rate-hz", o.rate_hz, "(0, 1000]");
  check(o.stale_ms > 0.0 && o.stale_ms <= 60000.0, "--stale-ms", o.stale_ms, "(0, 60000]");
  check(o.max_accel_mps2 > 0.0 && o.max_accel_mps2 <= 100.0, "--max-accel-mps2",
        o.max_accel_mps2, "(0, 100]");
  check(o.rt_priority >= 1 && o.rt_priority <= 99, "--rt-priority", o.rt_priority, "[1, 99]");
  check(o.max_cycles >= 0, "--max-cycles", static_cast<double>(o.max_cycles), "[0, inf)");
  check(o.idle_exit_s >= 0.0 && o.idle_exit_s <= 86400.0, "--idle-exit-s", o.idle_exit_s,
        "[0, 86400]");

  guidance_lcm::NodeConfig c;
  c.guidance.max_accel_mps2 = o.max_accel_mps2;
  c.guidance.nominal_cycle_s = 1.0 / o.rate_hz;
  c.guidance.stale_limit_s = o.stale_ms * 1e-3;
  c.stale_limit_s = o.stale_ms * 1e-3;
  c.lockstep = o.lockstep;
  c.armed = !o.start_disarmed;
  c.status_divider = o.status_divider;
  c.queue_capacity = o.queue_capacity;

  if (!o.scenario.empty()) {
    config::Scenario sc = config::Scenario::load(o.scenario);
    for (const auto& a : o.sets) sc.apply_override(a);
    const sim::SimConfig simc = sim::sim_config_from_scenario(sc);
    c.guidance = simc.guidance;
    c.armed = simc.armed && !o.start_disarmed;
    c.stale_limit_s = simc.guidance.stale_limit_s;
    if (o.accel_given) c.guidance.max_accel_mps2 = o.max_accel_mps2;
    if (o.stale_given) c.guidance.stale_limit_s = c.stale_limit_s = o.stale_ms * 1e-3;
    if (o.rate_given) c.guidance.nominal_cycle_s = 1.0 / o.rate_hz;
  }
  if (!o.config.empty()) {
    const config::Scenario s = config::Scenario::load(o.config);
    auto& g = c.guidance;
    g.max_accel_mps2 = s.get_double("guidance.max_accel_mps2", 1e-9, 100.0, g.max_accel_mps2);
    g.dv_budget_mps = s.get_double("guidance.dv_budget_mps", 1e-9, 1e4, g.dv_budget_mps);
    g.max_burn_s = s.get_double("guidance.max_burn_s", 1e-9, 1e5, g.max_burn_s);
    g.stale_limit_s = s.get_double("guidance.stale_limit_s", 1e-6, 60.0, g.stale_limit_s);
    g.nominal_cycle_s = s.get_double("guidance.nominal_cycle_s", 1e-6, 10.0, g.nominal_cycle_s);
    g.rate_noise_threshold_radps =
        s.get_double("guidance.rate_noise_threshold_radps", 0.0, 1.0, g.rate_noise_threshold_radps);
    g.rate_noise_k_sigma = s.get_double("guidance.rate_noise_k_sigma", 0.0, 100.0, g.rate_noise_k_sigma);
    g.zem_trigger_m = s.get_double("guidance.zem_trigger_m", 1e-9, 1e8, g.zem_trigger_m);
    g.min_track_updates =
        static_cast<int>(s.get_int("guidance.min_track_updates", 1, 1000, g.min_track_updates));
    auto& f = g.filter;
    f.process_noise_radps2 =
        s.get_double("guidance.filter.process_noise_radps2", 0.0, 1.0, f.process_noise_radps2);
    f.init_rate_sigma_radps =
        s.get_double("guidance.filter.init_rate_sigma_radps", 1e-12, 10.0, f.init_rate_sigma_radps);
    f.reinit_gap_s = s.get_double("guidance.filter.reinit_gap_s", 1e-6, 3600.0, f.reinit_gap_s);
    c.stale_limit_s = s.get_double("node.stale_limit_s", 1e-6, 60.0, c.stale_limit_s);
    c.future_tolerance_s = s.get_double("node.future_tolerance_s", 0.0, 10.0, c.future_tolerance_s);
    c.queue_capacity = static_cast<int>(s.get_int("node.queue_capacity", 1, 4096, c.queue_capacity));
    c.status_divider = static_cast<int>(s.get_int("node.status_divider", 1, 10000, c.status_divider));
    s.check_all_used();
  }
  const std::string err = c.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  return c;
}

}  // namespace evade::node
