// Conjunction screening cost (issue 6): robust all-pairs screening of seeded synthetic LEO
// populations over 1 day at a 5 km threshold on 2 threads, and the paper's adaptive step on
// its own case. Counters: pairs_checked (pairs sharing a grid cell), candidates (boxes
// overlap and apogee/perigee pass), events (approaches <= 5 km), all_pairs (N(N-1)/2).
// Two-body + J2 (issue 13): BM_ScreenJ2 (N, span [h], threads; process CPU time and wall
// time) and the target case BM_ScreenJ2Week (20 000 objects, 7 days, 2 threads).
// Run: build-dir/bench/conjunction_bench --benchmark_filter=Screen
// Results and machine: docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include "evade/conjunction/paper_step.hpp"
#include "evade/conjunction/population.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/core/elements.hpp"

namespace {

using namespace evade;
using namespace evade::conjunction;

// args range(0) = N; the grid step is step_s (0 = auto_step_s(N)).
void screen_population(benchmark::State& state, double span_s, double step_s,
                       GravityModel gravity = GravityModel::kTwoBody, int threads = 2) {
  PopulationOptions pop;
  pop.count = static_cast<std::size_t>(state.range(0));
  pop.seed = 2026;
  pop.span_s = span_s;
  const auto objects = synthetic_population(pop);
  ScreenOptions opt;
  opt.threshold_m = 5000.0;
  opt.step_s = step_s;
  opt.threads = threads;
  opt.gravity = gravity;
  ScreenResult r;
  for (auto _ : state) {
    r = screen_robust(objects, span_s, opt);
    benchmark::DoNotOptimize(r.events.data());
  }
  state.counters["pairs_checked"] = static_cast<double>(r.stats.pairs_checked);
  state.counters["candidates"] = static_cast<double>(r.stats.candidates);
  state.counters["events"] = static_cast<double>(r.events.size());
  state.counters["all_pairs"] = static_cast<double>(pop.count) * (pop.count - 1) / 2.0;
  state.counters["grid_steps"] = static_cast<double>(r.stats.steps);
  state.counters["narrow_intervals"] = static_cast<double>(r.stats.refined);
  state.counters["unproven_leaves"] = static_cast<double>(r.stats.unproven_leaves);
}

// Two-body + J2, 5 km, 60 s grid step; args: N, span [h], threads.
void BM_ScreenJ2(benchmark::State& state) {
  state.SetLabel("j2");
  screen_population(state, 3600.0 * static_cast<double>(state.range(1)), 60.0,
                    GravityModel::kTwoBodyJ2, static_cast<int>(state.range(2)));
}
void j2_args(benchmark::internal::Benchmark* b) {
  for (long n : {1000, 2000, 4000, 8000}) b->Args({n, 6, 1});
  for (long h : {3, 12, 24, 48}) b->Args({2000, h, 1});
  b->Args({4000, 6, 2});
}
BENCHMARK(BM_ScreenJ2)->Apply(j2_args)->MeasureProcessCPUTime()->UseRealTime()
    ->Unit(benchmark::kSecond)->Iterations(1);

// The target: 20 000 objects, 7 days, J2, 5 km, 2 threads (about an hour here).
void BM_ScreenJ2Week(benchmark::State& state) {
  screen_population(state, 7.0 * 86400.0, 60.0, GravityModel::kTwoBodyJ2, 2);
}
BENCHMARK(BM_ScreenJ2Week)->Args({20000})->MeasureProcessCPUTime()->UseRealTime()
    ->Unit(benchmark::kSecond)->Iterations(1);

// 1 day, 5 km, 2 threads; args: N, grid step [s] (0 = auto_step_s(N)).
void BM_ScreenOneDay(benchmark::State& state) {
  screen_population(state, 86400.0, static_cast<double>(state.range(1)));
}
BENCHMARK(BM_ScreenOneDay)
    ->Args({1000, 0})
    ->Args({10000, 0})
    ->Args({20000, 0})
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

// Growth of the cost with N (1 day would take long for the fit; 2 h keeps it quick).
void BM_ScreenScaling(benchmark::State& state) {
  screen_population(state, 7200.0, static_cast<double>(state.range(1)));
}
BENCHMARK(BM_ScreenScaling)
    ->Args({1000, 0})
    ->Args({2000, 0})
    ->Args({4000, 0})
    ->Args({8000, 0})
    ->Args({16000, 0})
    ->Args({32000, 0})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// Grid step trade-off at N = 10000 over 2 h.
void BM_ScreenStep(benchmark::State& state) {
  screen_population(state, 7200.0, static_cast<double>(state.range(1)));
}
BENCHMARK(BM_ScreenStep)
    ->Args({10000, 20})
    ->Args({10000, 30})
    ->Args({10000, 60})
    ->Args({10000, 120})
    ->Iterations(1)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime();

// The paper's method on its own 12-hour case (2 objects).
void BM_PaperSeed2(benchmark::State& state) {
  EarthModel earth;
  earth.mu_m3ps2 = 3.986005e14;
  OrbitalElements oe;
  std::vector<SpaceObject> objects(2);
  for (int k = 0; k < 2; ++k) {
    oe.a_m = 7371000.0;
    oe.i_rad = kPi / 2.0;
    oe.raan_rad = (k == 0 ? 70.0 : 250.0) * kDegToRad;
    objects[k].state = state_from_elements(oe, earth.mu_m3ps2);
  }
  objects[0].size_m = 1.0;
  objects[0].pos_error_m = 0.3;
  objects[1].size_m = 3.0;
  objects[1].pos_error_m = 0.5;
  long steps = 0;
  for (auto _ : state) {
    Ephemeris eph(objects, GravityModel::kTwoBody, earth);
    const PaperResult r = screen_paper(objects, 43200.0, PaperStepParams{}, eph, false);
    steps = r.steps;
    benchmark::DoNotOptimize(r.events.data());
  }
  state.counters["steps"] = static_cast<double>(steps);
}
BENCHMARK(BM_PaperSeed2)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
