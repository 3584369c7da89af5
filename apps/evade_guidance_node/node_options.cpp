// Options of evade_guidance_node (node_options.hpp): parse, then read every parameter
// through its table, so a bad value gives the same text here as in `evade sim`.
#include "node_options.hpp"

#include <stdexcept>

#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance_lcm/node_params.hpp"

namespace evade::node {

void add_options(CLI::App& app, NodeOptions& o) {
  app.add_option("--lcm-url", o.lcm_url, "LCM provider URL (e.g. udpm://239.255.76.67:7667?ttl=0, "
                                          "memq://, file:///path.log?speed=0)");
  app.add_option("--out-lcm-url", o.out_lcm_url,
                 "publish command/status on this URL instead (e.g. file:///out.log?mode=w)");
  const char* help[] = {"loop rate = guidance.rate_hz [Hz]",
                        "input stale limit = guidance.stale_limit_s [s]",
                        "maximum acceleration = guidance.max_accel_mps2 [m/s^2]",
                        "publish status every N cycles = node.status_divider",
                        "bounded input queue capacity = node.queue_capacity"};
  for (std::size_t i = 0; i < o.params.size(); ++i) {
    app.add_option(o.params[i].flag, o.params[i].value, help[i]);
  }
  app.add_flag("--lockstep", o.lockstep, "run one cycle per evade_sim_clock_t tick");
  app.add_flag("--realtime", o.realtime, "try SCHED_FIFO and mlockall (continues if refused)");
  app.add_option("--rt-priority", o.rt_priority, "SCHED_FIFO priority")
      ->check(CLI::Range(1, 99))->capture_default_str();
  app.add_option("--config", o.config, "optional YAML with guidance.* and node.* keys");
  app.add_option("--scenario", o.scenario,
                 "take guidance.* from this sim scenario, exactly as `evade sim` does (--config "
                 "and flags given explicitly still win)");
  app.add_option("--set", o.sets, "override a scenario key: --set key.path=value (repeatable)");
  app.add_option("--max-cycles", o.max_cycles, "stop after N cycles (0 = until SIGINT/SIGTERM)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--idle-exit-s", o.idle_exit_s,
                 "lockstep: exit after this long without a tick (0 = never)")
      ->check(CLI::Range(0.0, 86400.0));
  app.add_flag("--start-disarmed", o.start_disarmed, "start disarmed (evade_arm_t arms)");
  app.add_flag("--stats-json", o.stats_json, "print run statistics as JSON on stdout at exit");
  app.add_flag("--quiet", o.quiet, "no progress messages on stderr");
}

void note_given(const CLI::App& app, NodeOptions& o) {
  for (ParamFlag& f : o.params) f.given = app.count(f.flag) > 0;
}

namespace {

// The parameters under guidance.* and node.* of one scenario into c.
void read_node_params(const config::Scenario& sc, guidance_lcm::NodeConfig* c) {
  config::read_params(sc, "guidance.", guidance::guidance_params(), &c->guidance);
  config::read_params(sc, "node.", guidance_lcm::node_params(), c);
}

// One flag, read through its key's table row: the error names the flag and the key.
void apply_flag(const ParamFlag& f, guidance_lcm::NodeConfig* c) {
  config::Scenario one = config::Scenario::empty(std::string("flag ") + f.flag);
  one.apply_override(std::string(f.key) + "=" + param_value_text(f.value));
  read_node_params(one, c);
}

}  // namespace

guidance_lcm::NodeConfig make_node_config(const NodeOptions& o) {
  guidance_lcm::NodeConfig c;
  if (!o.scenario.empty()) {  // a sim scenario: only its guidance.* keys concern the node
    config::Scenario sc = config::Scenario::load(o.scenario);
    for (const auto& a : o.sets) sc.apply_override(a);
    config::read_params(sc, "guidance.", guidance::guidance_params(), &c.guidance);
  }
  if (!o.config.empty()) {
    const config::Scenario s = config::Scenario::load(o.config);
    read_node_params(s, &c);
    s.check_all_used();
  }
  for (const ParamFlag& f : o.params) {
    if (f.given) apply_flag(f, &c);
  }
  if (o.start_disarmed) c.guidance.armed = false;
  c.lockstep = o.lockstep;
  const std::string err = c.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  return c;
}

}  // namespace evade::node
