// The node's two schedulers (docs/GUIDANCE_NODE.md NODE-RT-*):
//  - fixed rate: absolute CLOCK_MONOTONIC deadlines (clock_nanosleep TIMER_ABSTIME), one
//    cycle per period; a cycle that ends after the next deadline is an overrun, counted, and
//    the schedule is re-anchored to the next future period boundary (no burst of catch-up
//    cycles). Cycle time stamps (utime) are CLOCK_REALTIME microseconds, like LCM's own.
//  - lockstep: one cycle per evade_sim_clock_t tick, at the tick's utime (deterministic).
#pragma once

#include <csignal>
#include <cstdint>
#include <vector>

#include "evade/guidance_lcm/guidance_node.hpp"

namespace evade::node {

struct LoopLimits {
  std::int64_t max_cycles = 0;    ///< 0 = until stop is set
  double idle_exit_s = 0.0;       ///< lockstep only: 0 = never
  bool progress = true;           ///< one line on stderr every ~10 s
  bool input_is_log = false;      ///< the input URL is a file:// log: its end exits 0
};

struct LoopResult {
  int exit_code = 0;
  const char* why = "";           ///< why the loop ended
  std::vector<double> wakeup_us;  ///< every wake-up latency (fixed rate, when max_cycles > 0)
  /// Lockstep: cycles whose compute took longer than the period of rate_hz. A lockstep cycle
  /// has no deadline (the tick starts it), so these are not overruns; they say which cycles
  /// would have missed the fixed-rate loop's.
  std::int64_t over_period = 0;
};

/// Runs until stop != 0, max_cycles, or (lockstep) input end / idle timeout.
LoopResult run_fixed_rate(guidance_lcm::GuidanceNode& node, double rate_hz, const LoopLimits& lim,
                          const volatile std::sig_atomic_t* stop);
LoopResult run_lockstep(guidance_lcm::GuidanceNode& node, double rate_hz, const LoopLimits& lim,
                        const volatile std::sig_atomic_t* stop);

/// SCHED_FIFO at priority and mlockall; says on stderr what was refused and continues.
/// Returns true if both succeeded.
bool try_realtime(int priority);

}  // namespace evade::node
