// 3D-Nc Pc cost (assessment/pc_3d_nc.hpp): one LEO conjunction with the default (Coppola)
// window, CARA's unit-test case testSimilarTo2D (target <= 20 ms on one core), and Alfano 2009
// case 01 (GEO, HBR 15 m, fixed window +-21600 s, the rate spread over the whole window).
// Counters: rate_evaluations (dNc/dt evaluations per call), pc. And the Monte Carlo's trials
// per second on one core (below).
// Run: build-dir/bench/pc_3d_nc_bench --benchmark_repetitions=5
#include <benchmark/benchmark.h>

#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/assessment/monte_carlo_pc.hpp"
#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/assessment/sphere_quadrature.hpp"
#include "data/cara_similar_to_2d.hpp"

namespace {

using namespace evade;
using namespace evade::assessment;

constexpr double kMu = 3.986004418e14;

using Leo = test_data::LeoCase;

Leo leo_case() { return test_data::cara_similar_to_2d(); }

void leo_similar_to_2d(benchmark::State& state) {
  const Leo k = leo_case();
  const StateEci& s1 = k.s1;
  const StateEci& s2 = k.s2;
  const Mat6& c1 = k.c1;
  const Mat6& c2 = k.c2;
  (void)sphere_rule(0);  // the rules are built once per process, outside the timing
  Nc3dResult r;
  for (auto _ : state) {
    r = pc_3d_nc(s1, c1, s2, c2, 20.0, kMu);
    benchmark::DoNotOptimize(r);  // not r.pc: GCC 12 takes the "+m,r" form through a GPR
  }
  state.counters["rate_evaluations"] = r.rate_evaluations;
  state.counters["pc"] = r.pc;
}
BENCHMARK(leo_similar_to_2d)->Name("BM_Pc3dNcLeoSimilarTo2D")->Unit(benchmark::kMillisecond);

// Alfano case 01 from its CDM, HBR 15 m.
ConjunctionInput alfano01() {
  std::ifstream in(std::string(EVADE_BENCH_ALFANO_DIR) + "/AlfanoTestCase01.cdm");
  if (!in) throw std::runtime_error("cannot open AlfanoTestCase01.cdm");
  std::stringstream ss;
  ss << in.rdbuf();
  return commands::conjunction_from_cdm(ccsds::read_cdm_text(ss.str()), 15.0, kEarthDefault);
}

void alfano_case01(benchmark::State& state) {
  const ConjunctionInput c = alfano01();
  Nc3dOptions opt;
  opt.window_s = 21600.0;
  (void)sphere_rule(0);
  Nc3dResult r;
  for (auto _ : state) {
    r = pc_3d_nc(c.obj[0].state, c.obj[0].cov_eci, c.obj[1].state, c.obj[1].cov_eci, c.hbr_m,
                 kMu, opt);
    benchmark::DoNotOptimize(r);  // not r.pc: GCC 12 takes the "+m,r" form through a GPR
  }
  state.counters["rate_evaluations"] = r.rate_evaluations;
  state.counters["pc"] = r.pc;
}
BENCHMARK(alfano_case01)->Name("BM_Pc3dNcAlfano01")->Unit(benchmark::kMillisecond);

// Monte Carlo trials per second on one core (monte_carlo_pc.hpp), one block of 10,000
// samples per iteration: the LEO case over +-600 s (two-body), and Alfano case 01 over
// +-21600 s. Counter trials_per_s (items_per_second).
void mc_run(benchmark::State& state, const McEncounter& e, double window_s) {
  MonteCarloOptions o;
  o.samples = kMcBlockSamples;
  o.window_s = window_s;
  o.threads = 1;
  MonteCarloResult r;
  for (auto _ : state) {
    r = pc_monte_carlo(e, o);
    benchmark::DoNotOptimize(r);
  }
  state.SetItemsProcessed(state.iterations() * o.samples);
  state.counters["pc"] = r.pc;
}

void mc_leo(benchmark::State& state) {
  const Leo k = leo_case();
  mc_run(state, McEncounter{k.s1, k.s2, k.c1, k.c2, 20.0, kEarthDefault}, 600.0);
}
BENCHMARK(mc_leo)->Name("BM_PcMonteCarloLeoSimilarTo2D")->Unit(benchmark::kMillisecond);

void mc_alfano01(benchmark::State& state) {
  const ConjunctionInput c = alfano01();
  mc_run(state, McEncounter{c.obj[0].state, c.obj[1].state, c.obj[0].cov_eci, c.obj[1].cov_eci,
                            15.0, kEarthDefault},
         21600.0);
}
BENCHMARK(mc_alfano01)->Name("BM_PcMonteCarloAlfano01")->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
