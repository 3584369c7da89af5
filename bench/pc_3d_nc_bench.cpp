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

#include "evade/assessment/conjunction_input.hpp"
#include "evade/assessment/monte_carlo_pc.hpp"
#include "evade/assessment/pc_3d_nc.hpp"
#include "evade/assessment/sphere_quadrature.hpp"

namespace {

using namespace evade;
using namespace evade::assessment;

constexpr double kMu = 3.986004418e14;

struct Leo {
  StateEci s1, s2;
  Mat6 c1, c2;
};

// CARA's testSimilarTo2D (Pc3D_Hall_UnitTest.m): states and 6x6 ECI covariances.
Leo leo_case() {
  Leo k;
  k.s1 = StateEci{Vec3(-9.841950433215101e+05, +3.932342044549424e+05, +6.991223682230414e+06),
                    Vec3(+4.883696742000000e+03, +5.689086045000000e+03, +3.665361590000000e+02)};
  k.s2 = StateEci{Vec3(-9.839696058965517e+05, +3.936845951174244e+05, +6.991219291625473e+06),
                    Vec3(+1.509562687000000e+03, +7.372938617000000e+03, -1.492509430000000e+02)};
  k.c1 << +4.976545641899520e+04, +5.787130862568278e+04, +3.370410320935015e+03, +1.137272273949272e+01, -4.325472616114674e+00, -8.009705480233521e+01,
      +5.787130862568278e+04, +6.730377643610841e+04, +3.926542932121541e+03, +1.321992688238858e+01, -5.035560720747812e+00, -9.314985106902773e+01,
      +3.370410320935015e+03, +3.926542932121541e+03, +2.461403197221289e+02, +7.586865834476763e-01, -3.077848629905763e-01, -5.434034460756914e+00,
      +1.137272273949272e+01, +1.321992688238858e+01, +7.586865834476763e-01, +2.608186227148725e-03, -9.804181796720670e-04, -1.829751672999786e-02,
      -4.325472616114674e+00, -5.035560720747812e+00, -3.077848629905763e-01, -9.804181796720670e-04, +3.895883508545853e-04, +6.968892326415779e-03,
      -8.009705480233521e+01, -9.314985106902773e+01, -5.434034460756914e+00, -1.829751672999786e-02, +6.968892326415779e-03, +1.289253320300791e-01;
  k.c2 << +4.246862551076427e+04, +2.066374367781032e+05, -5.011108933888592e+03, +3.104606531932427e+01, -1.201093683199582e+01, -2.207975848324051e+02,
      +2.066374367781032e+05, +1.005854717283451e+06, -2.434876491048039e+04, +1.510022508670080e+02, -5.850063541467530e+01, -1.074752763805685e+03,
      -5.011108933888592e+03, -2.434876491048039e+04, +6.131274993037449e+02, -3.667147183233717e+00, +1.391769957262238e+00, +2.601457791444154e+01,
      +3.104606531932427e+01, +1.510022508670080e+02, -3.667147183233717e+00, +2.272826228568773e-02, -8.778253314778023e-03, -1.613538091053610e-01,
      -1.201093683199582e+01, -5.850063541467530e+01, +1.391769957262238e+00, -8.778253314778023e-03, +3.428801115804722e-03, +6.251148178133809e-02,
      -2.207975848324051e+02, -1.074752763805685e+03, +2.601457791444154e+01, -1.613538091053610e-01, +6.251148178133809e-02, +1.148404222181769e+00;
  return k;
}

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
  return conjunction_from_cdm(read_cdm_text(ss.str()), 15.0, kEarthDefault);
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
