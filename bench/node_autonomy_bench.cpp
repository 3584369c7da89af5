// The guidance node's cycle while a conjunction is being planned beside it (docs/AUTONOMY.md
// AUT-8; docs/PERFORMANCE.md "Onboard conjunction response"). The node on memq:// with the
// ground's keys (test/guidance_lcm/conjunction_harness.hpp: the constructed LEO conjunction, the
// node's navigation flown along the event's own orbit), its planning worker on a thread of its
// own (as evade_guidance_node runs it: GuidanceNode::plan_once, 2 ms sleeps when idle), node
// defaults (8 candidate burn times). Each cycle's drain + run_cycle is timed, back to back:
//  BM_NodeCyclePlanningInFlight: only the cycles between an uplink and the node's decision of
//    that version (the job with the worker), over `versions` successive versions of the event,
//    each uplinked once the previous one is decided;
//  BM_NodeCycleTrackingNoPlanning: the same node and event, the cycles after the decision (the
//    event tracked, nothing being planned).
// Counters: p50_us, p99_us, max_us over the timed cycles, cycles, jobs.
#include <benchmark/benchmark.h>
#include <time.h>

#include <algorithm>
#include <atomic>
#include <thread>
#include <vector>

#include "guidance_lcm/conjunction_harness.hpp"

namespace {

using namespace evade;
using namespace evade::guidance_lcm;
using namespace evade::guidance_lcm::test;

std::int64_t now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

void report(benchmark::State& state, std::vector<double>& us, int jobs) {
  if (us.empty()) {
    state.SkipWithError("no cycle timed");
    return;
  }
  std::sort(us.begin(), us.end());
  auto q = [&](double p) { return us[static_cast<std::size_t>(p * static_cast<double>(us.size() - 1))]; };
  state.counters["p50_us"] = q(0.50);
  state.counters["p99_us"] = q(0.99);
  state.counters["max_us"] = us.back();
  state.counters["cycles"] = static_cast<double>(us.size());
  state.counters["jobs"] = jobs;
}

// The node's worker as evade_guidance_node runs it (apps/evade_guidance_node/planning_worker.hpp).
class Worker {
 public:
  explicit Worker(GuidanceNode& n) : n_(n), t_([this] { run(); }) {}
  ~Worker() {
    stop_.store(true);
    t_.join();
  }

 private:
  void run() {
    const timespec idle{0, 2'000'000};
    while (!stop_.load())
      if (!n_.plan_once()) (void)nanosleep(&idle, nullptr);
  }
  GuidanceNode& n_;
  std::atomic<bool> stop_{false};
  std::thread t_;
};

// One cycle at t: the nav sent (not timed), then drain + run_cycle timed [us].
double timed_cycle(Flight& f, std::int64_t t) {
  f.rig.pub.send(kChanNav, f.nav.at(t, ++f.nav_seq));
  const std::int64_t t0 = now_ns();
  f.rig.node.drain();
  (void)f.rig.node.run_cycle(t);
  return 1e-3 * static_cast<double>(now_ns() - t0);
}

// Runs cycles of f (timed: drain + run_cycle) until the node's proposal of version v leaves
// "assessing" (or max_cycles); returns the cycle time reached.
template <typename Record>
std::int64_t cycles_until_decided(Flight& f, std::int64_t t, std::int32_t v, long max_cycles,
                                  Record record) {
  for (long k = 0; k < max_cycles; ++k, t += kPeriodUs) {
    record(timed_cycle(f, t));
    const evade_cam_proposal_t* p = f.proposals.last(node_event().event_id, v);
    if (p != nullptr && p->state != evade_cam_proposal_t::STATE_ASSESSING) return t + kPeriodUs;
  }
  return t;
}

NodeConfig defaults() {
  NodeConfig c;
  c.autonomy = autonomy::Policy::kVeto;
  return c;  // the node's own burn search: 8 candidate times
}

void BM_NodeCyclePlanningInFlight(benchmark::State& state) {
  const int versions = static_cast<int>(state.range(0));
  std::vector<double> us;
  us.reserve(1 << 21);
  int jobs = 0;
  for (auto _ : state) {
    Flight f(defaults());
    Worker w(f.rig.node);
    std::int64_t t = kT0;
    for (std::int32_t v = 1; v <= versions; ++v) {
      autonomy::ConjunctionEvent e = node_event(7, v);
      f.rig.pub.send(kChanConjunction, conjunction_msg(e, v, t));
      t = cycles_until_decided(f, t, v, 2000000, [&](double x) {
        if (us.size() < us.capacity()) us.push_back(x);
      });
      ++jobs;
    }
  }
  report(state, us, jobs);
}
BENCHMARK(BM_NodeCyclePlanningInFlight)->Arg(5)->Iterations(1)->Unit(benchmark::kMillisecond);

void BM_NodeCycleTrackingNoPlanning(benchmark::State& state) {
  std::vector<double> us;
  us.reserve(1 << 20);
  for (auto _ : state) {
    Flight f(defaults());
    Worker w(f.rig.node);
    f.rig.pub.send(kChanConjunction, conjunction_msg(node_event(7, 1), 1, kT0));
    std::int64_t t = cycles_until_decided(f, kT0, 1, 2000000, [](double) {});
    for (int k = 0; k < 50000; ++k, t += kPeriodUs) us.push_back(timed_cycle(f, t));
  }
  report(state, us, 1);
}
BENCHMARK(BM_NodeCycleTrackingNoPlanning)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
