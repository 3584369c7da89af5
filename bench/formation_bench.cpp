// Paper 003 (formation collision avoidance by a small Δa): cost of the analytic Table 1
// (compute_limits), of the decision (a few propagations to the TCA), of the verification
// (two-body + J2 DOP853 propagation of the constrained satellites over burn + T = 3.5 days,
// 32 samples per period) and of one 3.68-day propagation with two burns and 1441 dense-output samples on its own.
#include <benchmark/benchmark.h>

#include "evade/commands/formation_scenario.hpp"
#include "evade/formation/verification.hpp"

namespace {

using namespace evade;
using namespace evade::formation;

const PlanInputs& seed3() {
  static const PlanInputs in = [] {
    const config::Scenario sc = config::Scenario::load("seed3");
    return commands::read_plan_inputs(sc);
  }();
  return in;
}

void BM_FormationLimits(benchmark::State& state) {
  const PlanInputs& in = seed3();
  for (auto _ : state) {
    LimitsResult r = compute_limits(in.spec, in.threatened);
    benchmark::DoNotOptimize(r);
  }
}
BENCHMARK(BM_FormationLimits);

void BM_FormationDecision(benchmark::State& state) {
  const PlanInputs& in = seed3();
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  for (auto _ : state) {
    Decision d = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
    benchmark::DoNotOptimize(d);
  }
}
BENCHMARK(BM_FormationDecision)->Unit(benchmark::kMillisecond);

void BM_FormationVerification(benchmark::State& state) {
  const PlanInputs& in = seed3();
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  const Decision dec = decide(in.spec, in.threatened, lim, in.conjunction, in.timing, in.propagation);
  for (auto _ : state) {
    Verification v = verify(in.spec, in.threatened, in.conjunction, dec, in.propagation);
    benchmark::DoNotOptimize(v);
  }
}
BENCHMARK(BM_FormationVerification)->Unit(benchmark::kMillisecond);

void BM_FormationPropagateOneSatellite3Days(benchmark::State& state) {
  const PlanInputs& in = seed3();
  const StateEci s0 = state_from_mean_elements(in.spec.groups[1].sats[0], in.spec.earth);
  std::vector<double> ts;
  for (int k = 0; k <= 32 * 45; ++k) ts.push_back(k * 7063.0 / 32.0);  // 1441 samples, 3.68 days
  for (auto _ : state) {
    auto st = propagate_with_burns(s0, ts, {{43200.0, 11.87}, {151200.0, -11.87}}, in.spec.earth,
                                   in.propagation.integrator);
    benchmark::DoNotOptimize(st);
  }
}
BENCHMARK(BM_FormationPropagateOneSatellite3Days)->Unit(benchmark::kMillisecond);

void BM_FormationNumericalLimits(benchmark::State& state) {
  const PlanInputs& in = seed3();
  const LimitsResult lim = compute_limits(in.spec, in.threatened);
  for (auto _ : state) {
    auto n = numerical_limits(in.spec, in.threatened, lim, 43200.0, in.propagation, 1e-3);
    benchmark::DoNotOptimize(n);
  }
}
BENCHMARK(BM_FormationNumericalLimits)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
