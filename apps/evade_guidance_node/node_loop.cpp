// Schedulers of evade_guidance_node (see node_loop.hpp).
#include "node_loop.hpp"

#include <sched.h>
#include <sys/mman.h>
#include <time.h>

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>

namespace evade::node {
namespace {

constexpr std::int64_t kNsPerS = 1000000000;

std::int64_t now_ns(clockid_t clk) {
  timespec ts{};
  clock_gettime(clk, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * kNsPerS + ts.tv_nsec;
}

timespec to_timespec(std::int64_t ns) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(ns / kNsPerS);
  ts.tv_nsec = static_cast<long>(ns % kNsPerS);
  return ts;
}

// The diagnostics below go to stderr; a failed print there has no recovery (there is nowhere
// else to report it) and must not stop the loop, so its result is discarded explicitly.
void progress_line(const guidance_lcm::GuidanceNode& node) {
  const auto& c = node.counts();
  (void)std::fprintf(stderr,
                     "evade_guidance_node: %lld cycles, mode %d, in %lld (consumed %lld "
                     "rejected %lld stale %lld superseded %lld dropped %lld), overruns %lld\n",
                     static_cast<long long>(node.cycles()), node.last_command().mode,
                     static_cast<long long>(c.received), static_cast<long long>(c.consumed),
                     static_cast<long long>(c.rejected), static_cast<long long>(c.stale),
                     static_cast<long long>(c.superseded), static_cast<long long>(c.dropped),
                     static_cast<long long>(node.compute_stats().overruns()));
}

// drain() < 0 ends the loop: SIGINT/SIGTERM arriving during LCM's select() makes it fail with
// EINTR, which is the requested stop ("signal", exit 0; it used to exit 1 and made one run in
// about twenty of `scripts/hil` fail); the end of a file:// log is a clean stop too; anything
// else is a receive error.
void end_on_drain_failure(const LoopLimits& lim, bool stopping, LoopResult* res) {
  if (stopping) return;
  res->exit_code = lim.input_is_log ? 0 : 1;
  res->why = lim.input_is_log ? "end of LCM input" : "LCM receive error";
}

}  // namespace

bool try_realtime(int priority) {
  bool ok = true;
  sched_param sp{};
  sp.sched_priority = priority;
  if (sched_setscheduler(0, SCHED_FIFO, &sp) != 0) {
    const int e = errno;
    (void)std::fprintf(stderr,
                       "evade_guidance_node: --realtime: SCHED_FIFO priority %d refused "
                       "(%s%s); continuing with the default scheduler, timing will be less "
                       "regular\n",
                       priority, std::strerror(e),
                       e == EPERM ? ": needs root, CAP_SYS_NICE or an rtprio limit" : "");
    ok = false;
  }
  if (mlockall(MCL_CURRENT | MCL_FUTURE) != 0) {
    const int e = errno;
    (void)std::fprintf(stderr,
                       "evade_guidance_node: --realtime: mlockall refused (%s%s); continuing "
                       "without locked memory, page faults may delay cycles\n",
                       std::strerror(e),
                       (e == EPERM || e == ENOMEM) ? ": needs CAP_IPC_LOCK or a memlock limit"
                                                   : "");
    ok = false;
  }
  return ok;
}

namespace {

// The wake-up after the deadline: its lateness recorded in the node's window and, while
// there is room reserved for it, in res. Returns the wake-up time [ns, CLOCK_MONOTONIC].
std::int64_t record_wakeup(guidance_lcm::GuidanceNode& node, std::int64_t deadline_ns,
                           LoopResult* res) {
  const std::int64_t wake = now_ns(CLOCK_MONOTONIC);
  const double late_us = static_cast<double>(wake - deadline_ns) * 1e-3;
  node.record_wakeup_latency(late_us);
  if (res->wakeup_us.size() < res->wakeup_us.capacity()) res->wakeup_us.push_back(late_us);
  return wake;
}

// One cycle after the wake-up at wake_ns: drain the inputs, step, persist. False when
// draining failed (the loop ends).
bool serve_cycle(guidance_lcm::GuidanceNode& node, std::int64_t wake_ns) {
  if (node.drain() < 0) return false;
  node.run_cycle(now_ns(CLOCK_REALTIME) / 1000);
  node.record_compute_time(static_cast<double>(now_ns(CLOCK_MONOTONIC) - wake_ns) * 1e-3);
  // Between cycles (AUTH-4): a command that advanced the anti-replay state waits for this
  // write; a failure is counted by the node and refuses the commands waiting on it.
  (void)node.persist_auth_state();
  return true;
}

}  // namespace

LoopResult run_fixed_rate(guidance_lcm::GuidanceNode& node, double rate_hz, const LoopLimits& lim,
                          const volatile std::sig_atomic_t* stop) {
  LoopResult res;
  if (lim.max_cycles > 0 && lim.max_cycles <= 10000000) {
    // Touched now (resize writes every element), so that recording a wake-up never faults a
    // fresh page in during the loop and the resident memory stays flat (scripts/soak).
    res.wakeup_us.resize(static_cast<std::size_t>(lim.max_cycles));
    res.wakeup_us.clear();
  }
  const std::int64_t period_ns = std::llround(1e9 / rate_hz);
  std::int64_t deadline = now_ns(CLOCK_MONOTONIC) + period_ns;
  std::int64_t next_progress = deadline + 10 * kNsPerS;
  while (*stop == 0) {
    const timespec ts = to_timespec(deadline);
    const int rc = clock_nanosleep(CLOCK_MONOTONIC, TIMER_ABSTIME, &ts, nullptr);
    if (rc == EINTR) continue;  // a signal: the loop condition decides
    const std::int64_t wake = record_wakeup(node, deadline, &res);
    if (!serve_cycle(node, wake)) {
      end_on_drain_failure(lim, *stop != 0, &res);
      break;
    }
    const std::int64_t done = now_ns(CLOCK_MONOTONIC);

    deadline += period_ns;
    if (done > deadline) {  // overrun: count once, re-anchor on the next future boundary
      node.record_overrun();
      deadline += ((done - deadline) / period_ns + 1) * period_ns;
    }
    if (lim.max_cycles > 0 && node.cycles() >= lim.max_cycles) {
      res.why = "max cycles reached";
      break;
    }
    if (lim.progress && done >= next_progress) {
      progress_line(node);
      next_progress = done + 10 * kNsPerS;
    }
  }
  if (*stop != 0) res.why = "signal";
  return res;
}

LoopResult run_lockstep(guidance_lcm::GuidanceNode& node, double rate_hz, const LoopLimits& lim,
                        const volatile std::sig_atomic_t* stop) {
  LoopResult res;
  const std::int64_t period_ns = std::llround(1e9 / rate_hz);
  std::int64_t last_tick = now_ns(CLOCK_MONOTONIC);
  std::int64_t next_progress = last_tick + 10 * kNsPerS;
  while (*stop == 0) {
    std::int64_t tick_utime = 0;
    const int rc = node.wait_for_tick(100, &tick_utime);
    const std::int64_t t = now_ns(CLOCK_MONOTONIC);
    if (rc < 0) {  // e.g. the end of a file:// log
      res.why = "end of LCM input";
      break;
    }
    if (rc == 0) {
      if (lim.idle_exit_s > 0.0 &&
          static_cast<double>(t - last_tick) * 1e-9 >= lim.idle_exit_s) {
        res.why = "idle timeout";
        break;
      }
      continue;
    }
    last_tick = t;
    node.run_cycle(tick_utime);
    const std::int64_t compute_ns = now_ns(CLOCK_MONOTONIC) - t;
    node.record_compute_time(static_cast<double>(compute_ns) * 1e-3);
    if (compute_ns > period_ns) ++res.over_period;
    (void)node.persist_auth_state();  // counted by the node (AUTH-4)
    if (lim.max_cycles > 0 && node.cycles() >= lim.max_cycles) {
      res.why = "max cycles reached";
      break;
    }
    if (lim.progress && t >= next_progress) {
      progress_line(node);
      next_progress = t + 10 * kNsPerS;
    }
  }
  if (*stop != 0) res.why = "signal";
  return res;
}

}  // namespace evade::node
