// The perigee/apogee filter of one satellite against a catalog
// (include/evade/conjunction/primary_prefilter.hpp gives the argument).
#include "evade/conjunction/primary_prefilter.hpp"

#include "evade/conjunction/primary_path_filter.hpp"

#include "evade/sgp4/sgp4.hpp"

#include <algorithm>
#include <cmath>
#include <thread>
#include <vector>

namespace evade::conjunction {
namespace {

// |r''| (scalar radius) <= |a| + v^2 / r <= kRadiusCurvature mu / r^2 (see the header).
constexpr double kRadiusCurvature = 3.1;

}  // namespace

// The radius every kPrefilterSampleS from t0_s to t1_s (both included), then the lower bound
// R raised by fixed point from the Earth radius: R <- min sample - B(R) h^2 / 8 with
// B(R) = kRadiusCurvature mu / R^2.
sgp4::RadiusBounds sampled_radius_bounds(const sgp4::Sgp4Propagator& p, double t0_s, double t1_s) {
  sgp4::RadiusBounds b;
  const long n = static_cast<long>(std::ceil((t1_s - t0_s) / kPrefilterSampleS));
  const double h = (t1_s - t0_s) / static_cast<double>(std::max(n, 1L));
  const sgp4::GravityConstants g = sgp4::gravity_constants(sgp4::GravityModel::kWgs72);
  const double mu = g.mu_km3ps2 * 1e9, re = g.radius_km * 1e3;  // the theory's constants
  double lo = 1e300, hi = 0.0;
  for (long k = 0; k <= n; ++k) {
    const sgp4::Sgp4State s = p.propagate_s(t0_s + static_cast<double>(k) * h);
    if (s.error != sgp4::Sgp4Error::kNone) return b;
    lo = std::min(lo, s.r_teme_m.norm());
    hi = std::max(hi, s.r_teme_m.norm());
  }
  double r = re;  // SGP4 reports decay below one Earth radius: r >= Re always
  for (int it = 0; it < 50; ++it) {
    const double next = lo - kRadiusCurvature * mu / (r * r) * h * h / 8.0;
    if (!(next > r * (1.0 + 1e-6))) break;
    r = next;
  }
  b.bounded = true;
  b.min_m = r;
  b.max_m = hi + kRadiusCurvature * mu / (r * r) * h * h / 8.0;
  return b;
}

namespace {

sgp4::RadiusBounds bounds_over(const sgp4::MeanElements& m, double start_j2000_s, double span_s,
                               long* sampled) {
  const double t0_s = start_j2000_s - sgp4::epoch_seconds_since_j2000(m) - kPrefilterPadS;
  const double t1_s = t0_s + span_s + 2.0 * kPrefilterPadS;
  const sgp4::Sgp4Propagator p(m, sgp4::OperationMode::kImproved);
  const sgp4::RadiusBounds b = p.radius_bounds(t0_s / 60.0, t1_s / 60.0);
  if (b.bounded || p.init_error() != sgp4::Sgp4Error::kNone) return b;
  ++*sampled;
  return sampled_radius_bounds(p, t0_s, t1_s);
}

}  // namespace

// Object k's radius bounds over the span, on `threads` threads (object k on thread k mod
// threads); sampled[k] is 1 when the bound came from samples.
std::vector<sgp4::RadiusBounds> all_bounds(const std::vector<sgp4::MeanElements>& all, double start_j2000_s,
                                           double span_s, int threads, std::vector<long>& sampled) {
  std::vector<sgp4::RadiusBounds> b(all.size());
  sampled.assign(all.size(), 0);
  const std::size_t n_threads = static_cast<std::size_t>(std::max(1, threads));
  const auto work = [&](std::size_t first) {
    for (std::size_t k = first; k < all.size(); k += n_threads)
      b[k] = bounds_over(all[k], start_j2000_s, span_s, &sampled[k]);
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < n_threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  return b;
}

namespace {

// Whether object j (bounds bj) may come within threshold_m of the primary (bounds p), counted.
bool may_come_within(const sgp4::RadiusBounds& p, const sgp4::RadiusBounds& bj, double threshold_m,
                     PrimaryPrefilterCounts& c) {
  if (!bj.bounded) {
    ++c.unbounded;
    return true;
  }
  const bool keep = bj.min_m <= p.max_m + threshold_m && bj.max_m >= p.min_m - threshold_m;
  if (!keep) ++c.removed_radius;
  return keep;
}

// The orbit-path filter over the padded span of each of `kept` but the primary (index
// primary in kept), on `threads` threads: never[k] = 1 when object k is set aside; the tests
// are added to c.
std::vector<char> path_filter_all(const std::vector<sgp4::MeanElements>& kept, std::size_t primary,
                                  double start_j2000_s, double span_s, double threshold_m,
                                  int threads, PrimaryPrefilterCounts& c) {
  std::vector<char> never(kept.size(), 0);
  std::vector<long> tests(kept.size(), 0);
  const auto offset = [&](std::size_t k) { return start_j2000_s - sgp4::epoch_seconds_since_j2000(kept[k]); };
  const sgp4::Sgp4Propagator p(kept[primary], sgp4::OperationMode::kImproved);
  if (p.deep_space() || p.init_error() != sgp4::Sgp4Error::kNone) return never;
  const std::size_t n_threads = static_cast<std::size_t>(std::max(1, threads));
  const auto work = [&](std::size_t first) {
    for (std::size_t k = first; k < kept.size(); k += n_threads) {
      if (k == primary) continue;
      const sgp4::Sgp4Propagator j(kept[k], sgp4::OperationMode::kImproved);
      const PathFilterResult r = path_never_within(p, offset(primary), j, offset(k), -kPrefilterPadS,
                                                   span_s + kPrefilterPadS, threshold_m);
      never[k] = r.never_within ? 1 : 0;
      tests[k] = r.tests;
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < n_threads; ++t) pool.emplace_back(work, t);
  work(0);
  for (std::thread& t : pool) t.join();
  for (long t : tests) c.path_tests += t;
  return never;
}

// The index of the first element set with this NORAD id, -1 when there is none.
long index_of(const std::vector<sgp4::MeanElements>& all, long norad) {
  for (std::size_t k = 0; k < all.size(); ++k)
    if (all[k].norad_id == norad) return static_cast<long>(k);
  return -1;
}

// Removes the entries k of v with marked[k] != 0, keeping the order; returns how many.
long drop_marked(std::vector<sgp4::MeanElements>& v, const std::vector<char>& marked) {
  std::size_t out = 0;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (marked[k] == 0) {
      if (out != k) v[out] = v[k];
      ++out;
    }
  const long dropped = static_cast<long>(v.size() - out);
  v.resize(out);
  return dropped;
}

}  // namespace

std::vector<sgp4::MeanElements> prefilter_primary(const std::vector<sgp4::MeanElements>& all,
                                                  long primary_norad, double start_j2000_s,
                                                  double span_s, double threshold_m,
                                                  PrimaryPrefilterCounts* counts, int threads,
                                                  bool path_filter) {
  PrimaryPrefilterCounts c;
  c.objects = static_cast<long>(all.size());
  const long primary = index_of(all, primary_norad);
  std::vector<long> sampled;
  const std::vector<sgp4::RadiusBounds> b =
      primary >= 0 ? all_bounds(all, start_j2000_s, span_s, threads, sampled) : std::vector<sgp4::RadiusBounds>{};
  const sgp4::RadiusBounds p = primary >= 0 ? b[static_cast<std::size_t>(primary)] : sgp4::RadiusBounds{};
  c.primary_bounded = p.bounded;
  if (primary >= 0) c.sampled = sampled[static_cast<std::size_t>(primary)];
  std::vector<sgp4::MeanElements> kept;
  std::size_t primary_kept = 0;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const bool others = p.bounded && static_cast<long>(k) != primary;
    if (others) c.sampled += sampled[k];
    if (static_cast<long>(k) == primary) primary_kept = kept.size();
    if (!others || may_come_within(p, b[k], threshold_m, c)) kept.push_back(all[k]);
  }
  if (path_filter && p.bounded) {
    const std::vector<char> never =
        path_filter_all(kept, primary_kept, start_j2000_s, span_s, threshold_m, threads, c);
    c.removed_path = drop_marked(kept, never);
  }
  c.kept = static_cast<long>(kept.size());
  if (counts) *counts = c;
  return kept;
}

}  // namespace evade::conjunction
