// The time filter of one satellite against a catalog (primary_time_filter.hpp gives the
// argument; Hoots, Crawford & Roehrich, Celestial Mechanics 33, 1984, for the idea).
#include "evade/conjunction/primary_time_filter.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <utility>

#include "evade/conjunction/primary_prefilter.hpp"

namespace evade::conjunction {
namespace {

// Allowed departure of the osculating semi-major axis from the radius range's mid-point, as a
// fraction of the largest radius (see the header: J2's short-period terms are 1.6e-3).
constexpr double kSemiMajorAxisMargin = 0.01;
// |r''| <= kGravityFactor mu / r^2 + kPerturbationAllowanceMps2 (see the header).
constexpr double kGravityFactor = 1.01;
constexpr double kPerturbationAllowanceMps2 = 1e-3;

// Appends [t0, t1] to the windows, merged with the last one when closer than gap_s.
void add_window(std::vector<TimeWindow>& w, double t0, double t1, double gap_s) {
  if (!w.empty() && t0 - w.back().t1_s <= gap_s) {
    w.back().t1_s = std::max(w.back().t1_s, t1);
    return;
  }
  w.push_back(TimeWindow{t0, t1});
}

// How long after the track's time k the pair stays farther than D (<= 0: it may not), or
// NaN (and the reason) when SGP4 fails or the speed check does not hold.
double safe_time_s(const PrimaryTrack& p, long k, const FilterObject& j, double d_m, std::string* why) {
  const double t = p.time_s(k);
  const sgp4::Sgp4State b = j.prop->propagate_s(j.offset_s + t);
  if (b.error != sgp4::Sgp4Error::kNone) {
    *why = "SGP4 error at t = " + std::to_string(t) + " s";
    return std::nan("");
  }
  if (b.v_teme_mps.norm() + kSpeedCheckMarginMps > j.speed_bound_mps) {
    *why = "SGP4 speed near its bound at t = " + std::to_string(t) + " s";
    return std::nan("");
  }
  const std::size_t i = static_cast<std::size_t>(k);
  const Eigen::Vector3d rho = b.r_teme_m - p.r_teme_m[i];
  const double d = rho.norm(), gap = d - d_m;
  if (!(gap > 0.0)) return 0.0;
  const double first = gap / (p.speed_bound_mps + j.speed_bound_mps);
  const double a = p.accel_bound_mps2 + j.accel_bound_mps2;
  const double rate = rho.dot(b.v_teme_mps - p.v_teme_mps[i]) / d -
                      velocity_allowance_mps(p.speed_bound_mps) - velocity_allowance_mps(j.speed_bound_mps);
  const double second = (rate + std::sqrt(rate * rate + 2.0 * a * gap)) / a;
  return std::max(first, second);
}

ObjectWindows whole_span(double span_s, std::string why, long evaluations) {
  ObjectWindows w;
  w.unfiltered = true;
  w.why_unfiltered = std::move(why);
  w.windows.push_back(TimeWindow{0.0, span_s});
  w.evaluations = evaluations;
  return w;
}

}  // namespace

FilterObject sgp4_motion_bounds(const sgp4::Sgp4Propagator& p, const sgp4::MeanElements& m,
                                double t0_s, double t1_s) {
  FilterObject f;
  if (!(m.mean_motion_revpday > 0.0) || p.init_error() != sgp4::Sgp4Error::kNone) return f;
  const double period_s = 86400.0 / m.mean_motion_revpday;
  t1_s = std::max(t1_s, t0_s + 1.1 * period_s);
  sgp4::RadiusBounds b = p.radius_bounds(t0_s / 60.0, t1_s / 60.0);
  if (!b.bounded) b = sampled_radius_bounds(p, t0_s, t1_s);
  if (!b.bounded || !(b.min_m > 0.0)) return f;
  const sgp4::GravityConstants g = sgp4::gravity_constants(sgp4::GravityModel::kWgs72);
  const double mu = g.mu_km3ps2 * 1e9;  // the theory's constant
  const double a_cap = 0.5 * (b.min_m + b.max_m) + kSemiMajorAxisMargin * b.max_m;
  f.speed_bound_mps = std::sqrt(mu * (2.0 / b.min_m - 1.0 / a_cap));
  f.accel_bound_mps2 = kGravityFactor * mu / (b.min_m * b.min_m) + kPerturbationAllowanceMps2;
  return f;
}

PrimaryTrack primary_track(const FilterObject& p, double span_s, const TimeFilterOptions& opt) {
  PrimaryTrack tr;
  tr.step_s = opt.min_window_s;
  tr.span_s = span_s;
  tr.speed_bound_mps = p.speed_bound_mps;
  tr.accel_bound_mps2 = p.accel_bound_mps2;
  if (!(p.speed_bound_mps > 0.0)) tr.why_unusable = "the primary has no speed bound";
  const long k_last = static_cast<long>(std::ceil(span_s / tr.step_s));
  tr.r_teme_m.resize(static_cast<std::size_t>(k_last) + 1);
  tr.v_teme_mps.resize(tr.r_teme_m.size());
  for (long k = 0; k <= k_last && tr.why_unusable.empty(); ++k) {
    const double t = tr.time_s(k);
    const sgp4::Sgp4State a = p.prop->propagate_s(p.offset_s + t);
    if (a.error != sgp4::Sgp4Error::kNone) tr.why_unusable = "primary: SGP4 error at t = " + std::to_string(t) + " s";
    else if (a.v_teme_mps.norm() + kSpeedCheckMarginMps > p.speed_bound_mps)
      tr.why_unusable = "primary: SGP4 speed near its bound at t = " + std::to_string(t) + " s";
    tr.r_teme_m[static_cast<std::size_t>(k)] = a.r_teme_m;
    tr.v_teme_mps[static_cast<std::size_t>(k)] = a.v_teme_mps;
  }
  return tr;
}

double PrimaryTrack::time_s(long k) const {
  return std::min(static_cast<double>(k) * step_s, span_s);
}

ObjectWindows primary_time_windows(const PrimaryTrack& p, const FilterObject& j,
                                   const TimeFilterOptions& opt) {
  const double span_s = p.span_s;
  if (!p.why_unusable.empty()) return whole_span(span_s, p.why_unusable, 0);
  if (!(j.speed_bound_mps > 0.0)) return whole_span(span_s, "no speed bound", 0);
  const long k_last = p.last(), w_max = std::max(1L, static_cast<long>(opt.max_window_s / p.step_s));
  ObjectWindows out;
  std::string why;
  long k = 0, w = 1, evaluated = -1;
  // Each pass raises k by at least one: at most K + 1 passes.
  for (long pass = 0; pass <= k_last && k <= k_last; ++pass) {
    const double safe_s = safe_time_s(p, k, j, opt.threshold_m, &why);
    ++out.evaluations;
    evaluated = k;
    if (std::isnan(safe_s)) return whole_span(span_s, why, out.evaluations);
    const long steps = static_cast<long>(std::floor(safe_s / p.step_s));
    if (steps >= 1) {  // d > D on [t_k, t_k + steps step_s] (the end is evaluated next)
      if (k == k_last) break;
      k = std::min(k_last, k + steps);
      w = 1;
      continue;
    }
    const long end = std::min(k_last, k + w);
    add_window(out.windows, p.time_s(std::min(k, end - 1)), p.time_s(end), opt.max_window_s);
    k += w;
    w = std::min(2 * w, w_max);
  }
  // SGP4 failing late in the span (decay) must not hide behind a window step.
  if (evaluated != k_last) {
    ++out.evaluations;
    if (std::isnan(safe_time_s(p, k_last, j, opt.threshold_m, &why))) return whole_span(span_s, why, out.evaluations);
  }
  return out;
}

}  // namespace evade::conjunction
