// Command-line and YAML options of evade_guidance_node (GUIDANCE_NODE.md NODE-CFG-*).
// Parameters come from their tables (guidance.*: guidance_params.hpp, node.*: node_params.hpp)
// in this order, later winning: defaults, --scenario (its guidance.* keys, as `evade sim`
// reads them), --config (guidance.* and node.* keys, unknown keys rejected), explicit flags.
// Every bad value is reported with the table's error text, naming the key (and the flag).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evade/core/param.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"

namespace evade::node {

struct NodeOptions {
  std::string lcm_url;            ///< "" = LCM default (LCM_DEFAULT_URL or udpm)
  std::string out_lcm_url;        ///< separate URL for the outputs ("" = same as lcm_url)
  bool lockstep = false;          ///< one cycle per evade_sim_clock_t tick
  bool realtime = false;          ///< try SCHED_FIFO + mlockall
  int rt_priority = 50;           ///< SCHED_FIFO priority [1, 99]
  std::string config;             ///< optional YAML (guidance.* and node.* keys)
  std::string scenario;           ///< optional sim scenario: its guidance.* keys
  std::vector<std::string> sets;  ///< key=value overrides of the scenario
  std::int64_t max_cycles = 0;    ///< stop after N cycles (0 = run until signalled)
  double idle_exit_s = 0.0;       ///< lockstep: exit 0 after this long without a tick (0 = never)
  bool start_disarmed = false;    ///< start disarmed (guidance.armed = false)
  std::string autonomy;           ///< --autonomy off|veto|approve ("" = NodeConfig's default, veto)
  bool stats_json = false;        ///< print the run's statistics as JSON on stdout at exit
  bool quiet = false;             ///< no progress on stderr
  std::vector<std::string> key_files;  ///< --keys (repeatable): docs/SECURITY.md KEY-1
  std::string auth_state;         ///< --auth-state: persisted key states and ARSNs (AUTH-4)
  std::int32_t auth_init = 0;     ///< --auth-init KEY_ID: first start (0: start from the file)
  std::int64_t auth_arsn_floor = 0;  ///< --auth-arsn-floor: with --auth-init, the command ARSNs' start
  std::string auth_commands;      ///< --auth-commands required|off (plan and arm channels)
  std::string auth_sensors;       ///< --auth-sensors required|off (nav, angles, sim clock)
  /// The parameter flags given (--guidance-rate-hz, --stale-limit-s, --max-accel-mps2,
  /// --status-divider, --queue-capacity), as typed values (evade/config/param_flags.hpp).
  std::vector<ParamValue> param_values;
};

/// Registers the flags on app.
void add_options(CLI::App& app, NodeOptions& o);
/// Builds the node configuration. Throws config::ConfigError or std::invalid_argument with
/// the key, the value and the allowed range.
guidance_lcm::NodeConfig make_node_config(const NodeOptions& o);
/// Loads --keys and --auth-state (docs/SECURITY.md KEY-1, AUTH-4). Throws std::runtime_error
/// naming the file (never a key byte) or std::invalid_argument for a missing --auth-state.
guidance_lcm::NodeSecurity make_node_security(const NodeOptions& o,
                                              const guidance_lcm::NodeConfig& cfg);

}  // namespace evade::node
