// The perigee/apogee filter of one satellite against a catalog
// (include/evade/conjunction/primary_prefilter.hpp gives the argument).
#include "evade/conjunction/primary_prefilter.hpp"

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

}  // namespace

std::vector<sgp4::MeanElements> prefilter_primary(const std::vector<sgp4::MeanElements>& all,
                                                  long primary_norad, double start_j2000_s,
                                                  double span_s, double threshold_m,
                                                  PrimaryPrefilterCounts* counts, int threads) {
  PrimaryPrefilterCounts c;
  c.objects = static_cast<long>(all.size());
  long primary = -1;
  for (std::size_t k = 0; k < all.size() && primary < 0; ++k)
    if (all[k].norad_id == primary_norad) primary = static_cast<long>(k);
  std::vector<long> sampled;
  const std::vector<sgp4::RadiusBounds> b =
      primary >= 0 ? all_bounds(all, start_j2000_s, span_s, threads, sampled) : std::vector<sgp4::RadiusBounds>{};
  const sgp4::RadiusBounds p = primary >= 0 ? b[static_cast<std::size_t>(primary)] : sgp4::RadiusBounds{};
  c.primary_bounded = p.bounded;
  if (primary >= 0) c.sampled = sampled[static_cast<std::size_t>(primary)];
  std::vector<sgp4::MeanElements> kept;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const bool others = p.bounded && static_cast<long>(k) != primary;
    if (others) c.sampled += sampled[k];
    if (!others || may_come_within(p, b[k], threshold_m, c)) kept.push_back(all[k]);
  }
  c.kept = static_cast<long>(kept.size());
  if (counts) *counts = c;
  return kept;
}

}  // namespace evade::conjunction
