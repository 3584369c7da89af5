// Screening a catalog with SGP4 motion (issue 12): the shipped 1,200-element-set catalog
// scenarios/catalogs/synthetic-1200.tle (generated to look like a public catalog:
// scenarios/catalogs/README.md), 5 km, from the latest element epoch.
//   BM_Sgp4CatalogSetup  : reading the file and sgp4_screening (SGP4 initialisation and the
//                          perturbation envelope of every object) for a span of range(0) h;
//   BM_Sgp4CatalogScreen : the all-pairs robust screening; args: span [h], threads;
//   BM_Sgp4CatalogPrimary: one object (NORAD 90000) against the catalog; args: span [h];
//   BM_Sgp4State         : one SGP4 state (position and SGP4's velocity) of every object of
//                          the catalog at 100 instants over a day; arg 0: the near-Earth
//                          objects (SGP4), 1: the deep-space ones (SDP4). Time per state.
//   BM_PathPieceTest     : one test of the orbit-path filter (a piece of 1,800 s, the primary
//                          90000 against each near-Earth object; primary_path_filter.hpp);
//   BM_Sgp4StateX4       : the states of BM_Sgp4State(arg), four at a time as the screening
//                          computes them (sgp4::Sgp4X4Lanes gathered once per group, then
//                          sgp4::propagate_x4; AVX2 where the processor has it).
// Run from the repository root (the catalog path is relative to it; EVADE_CATALOG overrides):
//   build/bench/catalog_screen_bench --benchmark_filter=Sgp4Catalog
// Results and machine: docs/PERFORMANCE.md.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "evade/conjunction/primary_path_filter.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/sgp4_motion.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace {

using namespace evade;
using namespace evade::conjunction;

bool read_catalog(benchmark::State& state, sgp4::Catalog& cat) {
  const char* env = std::getenv("EVADE_CATALOG");
  const std::string path = env ? env : "scenarios/catalogs/synthetic-1200.tle";
  std::ifstream in(path);
  if (!in) {
    state.SkipWithError(("cannot open " + path + " (run from the repository root)").c_str());
    return false;
  }
  std::ostringstream os;
  os << in.rdbuf();
  cat = sgp4::read_tle(os.str(), path);
  return true;
}

void BM_Sgp4CatalogSetup(benchmark::State& state) {
  sgp4::Catalog cat;
  if (!read_catalog(state, cat)) return;
  Sgp4MotionOptions mo;
  mo.span_s = 3600.0 * static_cast<double>(state.range(0));
  Sgp4Screening s;
  for (auto _ : state) {
    s = sgp4_screening(cat.objects, mo);
    benchmark::DoNotOptimize(s.objects.data());
  }
  state.counters["objects"] = static_cast<double>(s.objects.size());
  state.counters["rejected"] = static_cast<double>(s.rejected.size());
}
void BM_Sgp4State(benchmark::State& state) {
  sgp4::Catalog cat;
  if (!read_catalog(state, cat)) return;
  const bool deep = state.range(0) == 1;
  std::vector<sgp4::Sgp4Propagator> props;
  for (const auto& m : cat.objects) {
    sgp4::Sgp4Propagator p(m);
    if (p.init_error() == sgp4::Sgp4Error::kNone && p.deep_space() == deep) props.push_back(p);
  }
  long states = 0;
  for (auto _ : state) {
    for (int k = 0; k < 100; ++k) {
      for (const auto& p : props) {
        const sgp4::Sgp4State x = p.propagate_s(864.0 * k);
        benchmark::DoNotOptimize(x.r_teme_m.data());
      }
    }
    states += 100 * static_cast<long>(props.size());
  }
  state.counters["objects"] = static_cast<double>(props.size());
  state.counters["ns_per_state"] =
      benchmark::Counter(static_cast<double>(states) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_Sgp4State)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

// One test of the orbit-path filter (conjunction::path_piece_clear with the two bodies'
// sgp4::Sgp4Propagator::path_bounds over a 1,800 s piece): the primary 90000 against every
// other near-Earth object of the catalog, 24 pieces over a day. Time per test; the counter
// `cleared` is the fraction of tests that clear their piece at D = 5 km.
void BM_PathPieceTest(benchmark::State& state) {
  sgp4::Catalog cat;
  if (!read_catalog(state, cat)) return;
  std::vector<sgp4::Sgp4Propagator> props;
  for (const auto& m : cat.objects) {
    sgp4::Sgp4Propagator p(m);
    if (p.init_error() == sgp4::Sgp4Error::kNone && !p.deep_space()) props.push_back(p);
  }
  const sgp4::Sgp4Propagator& primary = props.front();
  long tests = 0, cleared = 0;
  for (auto _ : state) {
    for (int k = 0; k < 24; ++k) {
      const double t0_min = 30.0 * k, t1_min = t0_min + 30.0;
      const sgp4::PathBounds bp = primary.path_bounds(t0_min, t1_min);
      for (std::size_t j = 1; j < props.size(); ++j) {
        const bool clear = path_piece_clear(bp, props[j].path_bounds(t0_min, t1_min), 5000.0);
        cleared += clear ? 1 : 0;
      }
    }
    tests += 24 * static_cast<long>(props.size() - 1);
  }
  state.counters["cleared"] = static_cast<double>(cleared) / static_cast<double>(std::max(tests, 1L));
  state.counters["ns_per_test"] =
      benchmark::Counter(static_cast<double>(tests) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_PathPieceTest)->Unit(benchmark::kMillisecond);

// The states of BM_Sgp4State(arg), four objects at a time as the screening computes them:
// each group's constants gathered once (sgp4::Sgp4X4Lanes), then sgp4::propagate_x4 at every
// instant (propagate_near_x4, propagate_deep_x4 gather them at every call).
void BM_Sgp4StateX4(benchmark::State& state) {
  sgp4::Catalog cat;
  if (!read_catalog(state, cat)) return;
  const bool deep = state.range(0) == 1;
  std::vector<sgp4::Sgp4Propagator> props;
  for (const auto& m : cat.objects) {
    sgp4::Sgp4Propagator p(m);
    if (p.init_error() == sgp4::Sgp4Error::kNone && p.deep_space() == deep) props.push_back(p);
  }
  const std::size_t n4 = props.size() / 4 * 4;
  std::vector<sgp4::Sgp4X4Lanes> lanes;
  for (std::size_t g = 0; g < n4; g += 4) {
    const sgp4::Sgp4Propagator* p[4] = {&props[g], &props[g + 1], &props[g + 2], &props[g + 3]};
    lanes.emplace_back(p);
  }
  long states = 0;
  for (auto _ : state) {
    for (int k = 0; k < 100; ++k) {
      const double t = 864.0 * k / 60.0;
      const double tk[4] = {t, t, t, t};
      for (std::size_t g = 0; g < n4; g += 4) {
        const sgp4::Sgp4Propagator* p[4] = {&props[g], &props[g + 1], &props[g + 2], &props[g + 3]};
        double r[4][3], v[4][3];
        bool ok[4];
        sgp4::propagate_x4(lanes[g / 4], p, tk, r, v, ok);
        benchmark::DoNotOptimize(r);
      }
    }
    states += 100 * static_cast<long>(n4);
  }
  state.counters["objects"] = static_cast<double>(n4);
  state.counters["ns_per_state"] =
      benchmark::Counter(static_cast<double>(states) * 1e-9, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
  state.SetLabel(sgp4::sgp4_x4_vectorized() ? "AVX2" : "scalar lanes");
}
BENCHMARK(BM_Sgp4StateX4)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

BENCHMARK(BM_Sgp4CatalogSetup)->Arg(24)->Arg(168)->MeasureProcessCPUTime()->UseRealTime()
    ->Unit(benchmark::kSecond)->Iterations(1);

void screen(benchmark::State& state, double span_s, int threads, long primary_norad) {
  sgp4::Catalog cat;
  if (!read_catalog(state, cat)) return;
  Sgp4MotionOptions mo;
  mo.span_s = span_s;
  const Sgp4Screening s = sgp4_screening(cat.objects, mo);
  ScreenOptions opt;
  opt.motion = s.motion;
  opt.gravity = GravityModel::kTwoBodyJ2;
  opt.earth = wgs72_earth();
  opt.threshold_m = 5000.0;
  opt.include_warning_radius = false;
  opt.threads = threads;
  for (std::size_t k = 0; k < s.norad_ids.size(); ++k)
    if (s.norad_ids[k] == primary_norad) opt.primary = static_cast<long>(k);
  ScreenResult r;
  for (auto _ : state) {
    r = screen_robust(s.objects, span_s, opt);
    benchmark::DoNotOptimize(r.events.data());
  }
  state.counters["objects"] = static_cast<double>(s.objects.size());
  state.counters["events"] = static_cast<double>(r.events.size());
  state.counters["candidates"] = static_cast<double>(r.stats.candidates);
  state.counters["grid_steps"] = static_cast<double>(r.stats.steps);
  state.counters["unproven_leaves"] = static_cast<double>(r.stats.unproven_leaves);
}

void BM_Sgp4CatalogScreen(benchmark::State& state) {
  screen(state, 3600.0 * static_cast<double>(state.range(0)), static_cast<int>(state.range(1)), -1);
}
BENCHMARK(BM_Sgp4CatalogScreen)->Args({24, 1})->Args({24, 2})->Args({168, 2})
    ->MeasureProcessCPUTime()->UseRealTime()->Unit(benchmark::kSecond)->Iterations(1);

void BM_Sgp4CatalogPrimary(benchmark::State& state) {
  screen(state, 3600.0 * static_cast<double>(state.range(0)), 1, 90000);
}
BENCHMARK(BM_Sgp4CatalogPrimary)->Arg(24)->Arg(168)->MeasureProcessCPUTime()->UseRealTime()
    ->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace

BENCHMARK_MAIN();
