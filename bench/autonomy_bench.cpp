// The onboard conjunction response's decision (docs/AUTONOMY.md AUT-6; docs/PERFORMANCE.md
// "Onboard conjunction response"): autonomy::assess_event, the one computation the node's
// planning worker runs between the receipt of a conjunction and its proposal, on the
// constructed LEO example (test/autonomy/cam_example_event.hpp: Pc about 1e-3 above the red
// threshold 1e-4, the burn searched at 8 candidate times of the window), and on the same event
// moved 5 km apart (Pc below the threshold: the assessment alone). Timed here; counted in
// instructions by bench/count_instructions.sh (EVADE_COUNT_* below it).
#include <benchmark/benchmark.h>

#include <cstdint>

#include "autonomy/cam_example_event.hpp"
#include "evade/autonomy/orbit_stm.hpp"
#include "evade/autonomy/response.hpp"

namespace {

using evade::autonomy::PlanningJob;

// The navigation on the event's own orbit, carried back from TCA to now by the node's model.
PlanningJob job(const evade::autonomy::ConjunctionEvent& e) {
  PlanningJob j;
  j.event = e;
  j.now_us = evade::autonomy::test_example::kNow;
  j.nav_valid = true;
  j.x_nav_eci = e.x1_eci;
  (void)evade::autonomy::propagate(&j.x_nav_eci, -1e-6 * static_cast<double>(e.tca_us - j.now_us), 5.0,
                                   evade::kEarthDefault);
  return j;
}

evade::autonomy::ResponderConfig config() {
  evade::autonomy::ResponderConfig c;
  c.encounter = evade::assessment::encounter_2d_config(evade::assessment::AssessConfig{});
  return c;
}

evade::autonomy::CamWorkspace g_ws;

void run(benchmark::State& state, const PlanningJob& j, evade::autonomy::ResponseState want) {
  const evade::autonomy::ResponderConfig cfg = config();
  evade::autonomy::Assessment a;
  for (auto _ : state) {
    evade::autonomy::assess_event(j, cfg, evade::kEarthDefault, &g_ws, &a);
    benchmark::DoNotOptimize(a);
  }
  if (a.state != want) state.SkipWithError("the example did not give the expected decision");
}

void BM_AssessEventProposesABurn(benchmark::State& state) {
  evade::autonomy::ConjunctionEvent e = evade::autonomy::test_example::example_event();
  e.pc_target = 1e-5;
  e.veto_deadline_us = e.tca_us - static_cast<std::int64_t>(1.3 * evade::autonomy::test_example::kLeadS * 1e6);
  run(state, job(e), evade::autonomy::ResponseState::kProposed);
}
BENCHMARK(BM_AssessEventProposesABurn)->Unit(benchmark::kMillisecond);

void BM_AssessEventNoAction(benchmark::State& state) {
  evade::autonomy::ConjunctionEvent e = evade::autonomy::test_example::example_event();
  e.x2_eci[2] += 5000.0;
  run(state, job(e), evade::autonomy::ResponseState::kNoAction);
}
BENCHMARK(BM_AssessEventNoAction)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
