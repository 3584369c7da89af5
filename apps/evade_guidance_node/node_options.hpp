// Command-line and YAML options of evade_guidance_node (design_node.md NODE-CFG-*).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evade/guidance_lcm/node_core.hpp"

namespace evade::node {

struct NodeOptions {
  std::string lcm_url;            ///< "" = LCM default (LCM_DEFAULT_URL or udpm)
  std::string out_lcm_url;        ///< separate URL for the outputs ("" = same as lcm_url)
  double rate_hz = 50.0;          ///< fixed-rate loop frequency [Hz], (0, 1000]
  bool lockstep = false;          ///< one cycle per evade_sim_clock_t tick
  bool realtime = false;          ///< try SCHED_FIFO + mlockall
  int rt_priority = 50;           ///< SCHED_FIFO priority [1, 99]
  double stale_ms = 500.0;        ///< input stale limit [ms]
  double max_accel_mps2 = 1.0;    ///< maximum commanded acceleration [m/s^2]
  std::string config;             ///< optional YAML (guidance.* and node.* keys)
  std::string scenario;           ///< optional sim scenario: guidance.* read as `evade sim` does
  std::vector<std::string> sets;  ///< key=value overrides of the scenario
  bool rate_given = false, stale_given = false, accel_given = false;  ///< set after parsing
  std::int64_t max_cycles = 0;    ///< stop after N cycles (0 = run until signalled)
  double idle_exit_s = 0.0;       ///< lockstep: exit 0 after this long without a tick (0 = never)
  bool start_disarmed = false;    ///< start disarmed (evade_arm_t arms)
  int status_divider = 1;         ///< status every N cycles
  int queue_capacity = 16;        ///< bounded input queue
  bool stats_json = false;        ///< print the run's statistics as JSON on stdout at exit
  bool quiet = false;             ///< no progress on stderr
};

/// Registers the flags on app.
void add_options(CLI::App& app, NodeOptions& o);
/// Records which flags were given explicitly (call after app.parse()).
void note_given(const CLI::App& app, NodeOptions& o);
/// Builds the node configuration from the options and the optional YAML file. Throws
/// config::ConfigError or std::invalid_argument with the key, value and allowed range.
guidance_lcm::NodeConfig make_node_config(const NodeOptions& o);

}  // namespace evade::node
