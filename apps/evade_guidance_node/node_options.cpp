// Options of evade_guidance_node (node_options.hpp): parse, then read every parameter
// through its table, so a bad value gives the same text here as in `evade sim`.
#include "node_options.hpp"

#include <time.h>

#include <cstdint>
#include <fstream>
#include <stdexcept>

#include "evade/auth/key_file.hpp"
#include "param_flag_option.hpp"

#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance_lcm/node_params.hpp"

namespace evade::node {

namespace {

// The flags of the parameters the node reads (evade/config/param_flags.hpp): guidance.* and
// node.* keys, each declared with its row.
void add_param_flags(CLI::App& app, NodeOptions& o) {
  for (const char* key : {"guidance.rate_hz", "guidance.stale_limit_s", "guidance.max_accel_mps2"}) {
    (void)cli::add_param_flag(app, guidance::guidance_params(), "guidance.", key, &o.param_values);
  }
  for (const char* key : {"node.status_divider", "node.queue_capacity"}) {
    (void)cli::add_param_flag(app, guidance_lcm::node_params(), "node.", key, &o.param_values);
  }
}

void add_auth_options(CLI::App& app, NodeOptions& o) {
  app.add_option("--keys", o.key_files,
                 "key file written by `evade keygen` (mode 0600; repeatable): command, sensor "
                 "and telemetry keys (docs/SECURITY.md)");
  app.add_option("--auth-state", o.auth_state,
                 "file of the persisted key states and command ARSNs (required with command "
                 "keys; the node starts only from a valid one, or with --auth-init)");
  app.add_option("--auth-init", o.auth_init,
                 "first start only: write a new --auth-state (refused if one exists) with this "
                 "command key active and the others standby [-]")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--auth-arsn-floor", o.auth_arsn_floor,
                 "with --auth-init: every command ARSN starts here (recovery after a lost state "
                 "file: the ground's last ARSN, docs/SECURITY.md) [-]")
      ->check(CLI::Range(static_cast<std::int64_t>(0), INT64_MAX));
  app.add_option("--auth-commands", o.auth_commands,
                 "required|off: plans and arm commands must be signed = node.auth.plan_required, "
                 "node.auth.arm_required (default required)")
      ->check(CLI::IsMember({"required", "off"}));
  app.add_option("--auth-sensors", o.auth_sensors,
                 "required|off: nav, angles and sim-clock messages must be signed = "
                 "node.auth.nav_required, .angles_required, .clock_required (default off)")
      ->check(CLI::IsMember({"required", "off"}));
}

}  // namespace

void add_options(CLI::App& app, NodeOptions& o) {
  app.add_option("--lcm-url", o.lcm_url, "LCM provider URL (e.g. udpm://239.255.76.67:7667?ttl=0, "
                                          "memq://, file:///path.log?speed=0)");
  app.add_option("--out-lcm-url", o.out_lcm_url,
                 "publish command/status on this URL instead (e.g. file:///out.log?mode=w)");
  add_param_flags(app, o);
  app.add_flag("--lockstep", o.lockstep, "run one cycle per evade_sim_clock_t tick");
  app.add_flag("--realtime", o.realtime, "try SCHED_FIFO and mlockall (continues if refused)");
  app.add_option("--rt-priority", o.rt_priority, "SCHED_FIFO priority [-]")
      ->check(CLI::Range(1, 99))->capture_default_str();
  app.add_option("--config", o.config, "optional YAML with guidance.* and node.* keys");
  app.add_option("--scenario", o.scenario,
                 "take guidance.* from this sim scenario, exactly as `evade sim` does (--config "
                 "and flags given explicitly still win)");
  app.add_option("--set", o.sets, "override a scenario key: --set key.path=value (repeatable)");
  app.add_option("--max-cycles", o.max_cycles, "stop after N cycles [-] (0 = until SIGINT/SIGTERM)")
      ->check(CLI::NonNegativeNumber);
  app.add_option("--idle-exit-s", o.idle_exit_s,
                 "lockstep: exit after this long without a tick [s] (0 = never)")
      ->check(CLI::Range(0.0, 86400.0));
  app.add_flag("--start-disarmed", o.start_disarmed, "start disarmed (evade_arm_t arms)");
  app.add_option("--autonomy", o.autonomy,
                 "off|veto|approve: the onboard conjunction response's policy at start (off: "
                 "assess and report only; veto: burn at the proposed time unless the ground "
                 "vetoes before the deadline; approve: burn only when approved; the ground's "
                 "evade_cam_decision_t changes it; docs/AUTONOMY.md) (default veto)")
      ->check(CLI::IsMember({"off", "veto", "approve"}));
  app.add_flag("--stats-json", o.stats_json, "print run statistics as JSON on stdout at exit");
  app.add_flag("--quiet", o.quiet, "no progress messages on stderr");
  add_auth_options(app, o);
}

namespace {

// The parameters under guidance.* and node.* of one scenario into c.
void read_node_params(const config::Scenario& sc, guidance_lcm::NodeConfig* c) {
  config::read_params(sc, "guidance.", guidance::guidance_params(), &c->guidance);
  config::read_params(sc, "node.", guidance_lcm::node_params(), c);
  config::read_params(sc, "node.autonomy.", autonomy::responder_params(), &c->response);
  config::read_params(sc, "node.autonomy.cam.", autonomy::cam_options_params(), &c->response.cam);
}

// The parameter flags given, read through their keys' tables (already checked at parse).
void apply_flags(const NodeOptions& o, guidance_lcm::NodeConfig* c) {
  if (o.param_values.empty()) return;
  config::Scenario flags = config::Scenario::empty("command-line flags");
  for (const ParamValue& v : o.param_values) flags.set_value(v);
  read_node_params(flags, c);
}

}  // namespace

guidance_lcm::NodeConfig make_node_config(const NodeOptions& o) {
  guidance_lcm::NodeConfig c;
  if (!o.scenario.empty()) {  // a sim scenario: only its guidance.* keys concern the node
    config::Scenario sc = config::Scenario::load(o.scenario);
    for (const auto& a : o.sets) sc.apply_override(a);
    config::read_params(sc, "guidance.", guidance::guidance_params(), &c.guidance);
  }
  if (!o.config.empty()) {  // a file of the node's keys, named as such when it is missing
    if (!std::ifstream(o.config).good())
      throw std::invalid_argument("--config: file '" + o.config + "' not found or unreadable");
    const config::Scenario s = config::Scenario::load(o.config);
    read_node_params(s, &c);
    s.check_all_used();
  }
  apply_flags(o, &c);
  if (!o.auth_commands.empty()) {
    c.auth.plan_required = c.auth.arm_required = o.auth_commands == "required";
  }
  if (!o.auth_sensors.empty()) {
    const bool on = o.auth_sensors == "required";
    c.auth.nav_required = c.auth.angles_required = c.auth.clock_required = on;
  }
  if (o.start_disarmed) c.guidance.armed = false;
  if (!o.autonomy.empty()) (void)autonomy::parse_policy(o.autonomy.c_str(), &c.autonomy);  // checked at parse
  c.lockstep = o.lockstep;
  const std::string err = c.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  return c;
}

// AUTH-4, TM-1: command keys need the state file (the anti-replay state must survive a restart)
// and the telemetry key (the ground acts only on signed acknowledgements).
guidance_lcm::NodeSecurity make_node_security(const NodeOptions& o,
                                              const guidance_lcm::NodeConfig& cfg) {
  guidance_lcm::NodeSecurity sec;
  for (const std::string& f : o.key_files) auth::load_into(auth::read_key_file(f), &sec.keys);
  bool command_keys = false;
  for (std::size_t i = 0; i < sec.keys.size(); ++i) {
    command_keys = command_keys || sec.keys.entry(i).role == auth::KeyRole::kCommand;
  }
  if (command_keys && o.auth_state.empty()) {
    throw std::invalid_argument(
        "command keys (--keys) need --auth-state FILE: the anti-replay state must survive a "
        "restart (docs/SECURITY.md AUTH-4)");
  }
  if (command_keys && sec.keys.telemetry_key() == nullptr) {
    throw std::invalid_argument(
        "command keys (--keys) need a telemetry key too (`evade keygen --role telemetry`): the "
        "node signs its acknowledgements with it, and the ground acts on no other "
        "(docs/SECURITY.md TM-1)");
  }
  if (o.auth_init == 0 && o.auth_arsn_floor != 0) {
    throw std::invalid_argument("--auth-arsn-floor applies only with --auth-init");
  }
  if (o.auth_init != 0 && o.auth_state.empty()) {
    throw std::invalid_argument("--auth-init needs --auth-state FILE");
  }
  sec.state_path = o.auth_state;
  sec.init_active_key = o.auth_init;
  sec.init_arsn_floor = o.auth_arsn_floor;
  if (!cfg.lockstep) {  // fixed rate: sensor ARSNs (the signer's CLOCK_REALTIME) after our start
    timespec ts{};
    (void)clock_gettime(CLOCK_REALTIME, &ts);  // CLOCK_REALTIME always exists: cannot fail
    sec.sensor_arsn_floor_us = static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
  }
  return sec;
}

}  // namespace evade::node
