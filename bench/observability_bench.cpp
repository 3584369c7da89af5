// Speed of the paper-004 observability planner (NLopt ISRES + BOBYQA polish) and of one
// evaluation of each objective, on the seed4 problem (scenarios/seed4.yaml).
// Must show: one plan of the `paper` objective in < 0.5 s on one core.
#include <benchmark/benchmark.h>

#include <cmath>

#include "evade/observability/planner.hpp"

namespace {

using namespace evade::observability;

SampledProblem seed4() {
  ObservabilityProblem p;
  p.n_radps = std::sqrt(3.986004418e14 / std::pow(6378137.0 + 400e3, 3));
  p.x_chaser_p0 << 79933.5, -57232.0, 0.0, -11.135, 2.38, 0.0;
  return sample(p);
}

void plan(benchmark::State& state, ObjectiveKind k, int budget) {
  const SampledProblem s = seed4();
  IsresOptions o;
  o.max_evaluations = budget;
  int evals = 0;
  double theta = 0;
  for (auto _ : state) {
    const PlanResult r = plan_isres(s, k, EstimationConfig{}, o);
    evals = r.evaluations;
    theta = r.theta_rad;
    benchmark::DoNotOptimize(theta);
  }
  state.counters["evaluations"] = evals;
  state.counters["theta_rad"] = theta;
}

void BM_PlanPaper(benchmark::State& s) { plan(s, ObjectiveKind::kPaper, 2400); }
void BM_PlanLosChange(benchmark::State& s) { plan(s, ObjectiveKind::kLosChange, 2400); }
void BM_PlanEstimation300(benchmark::State& s) { plan(s, ObjectiveKind::kEstimation, 300); }

void BM_EvalPaper(benchmark::State& state) {
  const SampledProblem s = seed4();
  for (auto _ : state) benchmark::DoNotOptimize(paper_objective(s, 0.0, -3.2456));
}
void BM_EvalLosChange(benchmark::State& state) {
  const SampledProblem s = seed4();
  for (auto _ : state) benchmark::DoNotOptimize(los_change(s, 0.0, -3.2456).sum_rad);
}
void BM_EvalEstimation(benchmark::State& state) {
  const SampledProblem s = seed4();
  const evade::Vec3 dv = dv_paper_from_angles(0.0, -3.2456, 3.0);
  for (auto _ : state) benchmark::DoNotOptimize(estimate_angles_only(s, EstimationConfig{}, dv).major_axis_m);
}
void BM_Sample(benchmark::State& state) {
  for (auto _ : state) benchmark::DoNotOptimize(seed4().t_s.size());
}

BENCHMARK(BM_PlanPaper)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanLosChange)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_PlanEstimation300)->Unit(benchmark::kMillisecond)->Iterations(3);
BENCHMARK(BM_EvalPaper)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvalLosChange)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_EvalEstimation)->Unit(benchmark::kMicrosecond);
BENCHMARK(BM_Sample)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
