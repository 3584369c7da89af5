// The robust screener's step runner (issue 6; internal/step_runner.hpp): the grid steps
// [k_begin, k_end) of a screening by blocks of grid steps, on std::thread workers. For each
// block the threads first advance every object through the block's grid times (objects split
// between them in chunks; under two-body + J2 each object's DOP853 integrator steps through
// every grid time from t = 0), then screen the block's steps (steps split between them, one
// Worker each: screen_worker.hpp). Each object's states at the grid times do not depend on
// the split, so neither do the events (robust_screen.hpp). Under two-body every object keeps
// the conic's radius range over the whole span (exact bounds).
#include "evade/conjunction/internal/step_runner.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <exception>
#include <thread>
#include <utility>
#include <vector>

namespace evade::conjunction::internal {
namespace {

// Two-body: the conic's radius range holds over the whole span (exact bounds).
std::vector<ArcBounds> conic_bounds(const std::vector<ObjectBounds>& ob, const EarthModel& earth) {
  std::vector<ArcBounds> b(ob.size());
  for (std::size_t k = 0; k < ob.size(); ++k) {
    b[k].r_lo_m = ob[k].r_min_m;
    b[k].r_hi_m = ob[k].r_max_m;
    b[k].g_max_mps2 = ob[k].g_max_mps2;
    b[k].v_max_mps = std::sqrt(2.0 * earth.mu_m3ps2 / ob[k].r_min_m);
  }
  return b;
}

// Runs body(t) on threads t = 0 .. nthreads - 1 (t = 0 on the calling thread); rethrows the
// first exception.
template <class Body>
void run_parallel(int nthreads, const Body& body) {
  if (nthreads == 1) {
    body(0);
    return;
  }
  std::vector<std::thread> threads;
  std::vector<std::exception_ptr> errors(static_cast<std::size_t>(nthreads));
  for (int t = 1; t < nthreads; ++t) {
    threads.emplace_back([&body, &errors, t]() {
      try {
        body(t);
      } catch (...) {
        errors[static_cast<std::size_t>(t)] = std::current_exception();
      }
    });
  }
  try {
    body(0);
  } catch (...) {
    errors[0] = std::current_exception();
  }
  for (auto& th : threads) th.join();
  for (auto& e : errors)
    if (e) std::rethrow_exception(e);
}

}  // namespace

StepRunner::StepRunner(const std::vector<SpaceObject>& objects,
                       const std::vector<ObjectBounds>& bounds, const ScreenOptions& opt,
                       double span_s, long nsteps, int nthreads)
    : objects_(objects), opt_(opt), span_s_(span_s), nsteps_(nsteps), nthreads_(nthreads),
      eph_(objects, opt.gravity, opt.earth, opt.integ, opt.motion) {
  const double d_max = max_reporting_distance_m(objects, opt);
  const std::vector<ArcBounds> conic = conic_bounds(bounds, opt.earth);
  std::vector<double> size_m(objects.size());
  for (std::size_t i = 0; i < objects.size(); ++i)
    size_m[i] = objects[i].size_m + objects[i].pos_error_m;
  workers_.reserve(static_cast<std::size_t>(nthreads));
  for (int t = 0; t < nthreads; ++t) workers_.emplace_back(objects, opt, eph_, d_max, conic, size_m);
}

void StepRunner::run(long k_begin, long k_end, ScreenResult& res) {
  const std::size_t n = objects_.size();
  // Grid states of one block: rows_[m] at grid time k0 + m.
  const long block = std::clamp<long>(static_cast<long>(1'000'000 / std::max<std::size_t>(n, 1)), 4, 64);
  rows_.assign(static_cast<std::size_t>(block) + 1, std::vector<StateEci>(n));
  // J2: every grid time before k_begin (the integrators' steps end on each of them).
  const bool replay = opt_.gravity == GravityModel::kTwoBodyJ2 && !opt_.motion;  // DOP853 steps
  const long k_first = replay ? 0 : k_begin;
  advance(k_first, k_begin, k_begin);
  for (long k0 = k_begin; k0 < k_end; k0 += block) {
    const long k1 = std::min(k_end, k0 + block);
    if (k0 != k_begin) std::swap(rows_[0], rows_[static_cast<std::size_t>(block)]);
    advance(k0 + 1, k1, k0);
    screen_steps(k0, k1);
    if (opt_.progress) {
      opt_.progress(static_cast<double>(k1 - k_begin) / static_cast<double>(k_end - k_begin));
    }
  }
  for (auto& w : workers_) {
    res.events.insert(res.events.end(), w.events.begin(), w.events.end());
    add_stats(res.stats, w.stats);
  }
}

void StepRunner::advance(long k_from, long k_to, long k_row0) {
  if (k_from > k_to) return;
  constexpr std::size_t kChunk = 64;  // objects (Sgp4Motion's lane groups come in windows of 64)
  const std::size_t n = objects_.size();
  std::atomic<std::size_t> next{0};
  run_parallel(nthreads_, [&](int) {
    for (std::size_t b = next.fetch_add(kChunk); b < n; b = next.fetch_add(kChunk)) {
      const std::size_t e = std::min(n, b + kChunk);
      for (long k = k_from; k <= k_to; ++k) {
        std::vector<StateEci>& row = rows_[static_cast<std::size_t>(std::max(k - k_row0, 0L))];
        eph_.grid_states_at(grid_time(k), b, e, row.data());
      }
    }
  });
}

void StepRunner::screen_steps(long k0, long k1) {
  std::atomic<long> next{k0};
  run_parallel(nthreads_, [&](int t) {
    Worker& w = workers_[static_cast<std::size_t>(t)];
    for (long k = next.fetch_add(1); k < k1; k = next.fetch_add(1)) {
      const std::size_t m = static_cast<std::size_t>(k - k0);
      w.screen_step(rows_[m].data(), rows_[m + 1].data(), grid_time(k), grid_time(k + 1));
    }
  });
}

}  // namespace evade::conjunction::internal
