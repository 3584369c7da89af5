// Bounds of the SGP4 radius over an interval of time, from the near-Earth theory's formulas
// (Vallado, Crawford, Hujsak & Kelso 2006, "Revisiting Spacetrack Report #3", sgp4 as in
// sgp4.cpp), for the perigee/apogee filter of catalog screening (in the manner of the first
// of Hoots, Crawford & Roehrich's filters, "An analytic method to determine future close
// approaches between satellites", Celestial Mechanics 33, 1984).
//
// Argument, with t in [t0, t1] (minutes from the epoch) and the quantities of propagate_min:
//  1. am = (xke / no)^(2/3) tempa^2, tempa = 1 - C1 t - D2 t^2 - D3 t^3 - D4 t^4 (D2..D4 = 0
//     in the simplified mode). Each monomial's range over [t0, t1] is exact (t^k is monotone,
//     or even with its minimum 0 inside); their interval sum bounds tempa. tempa_lo > 0 is
//     required (else drag ends the orbit inside the interval: no bound).
//  2. em = e0 - tempe, tempe = B* C4 t + B* C5 (sin M - sin M0): |B* C5 (sin M - sin M0)| <=
//     2 |B* C5|; the theory clamps em to >= 1e-6 and fails for em >= 1: |em| <= em_max.
//  3. axnl = em cos w, aynl = em sin w + aycof / (am (1 - em^2)), so the Lyddane
//     eccentricity el = |(axnl, aynl)| <= em_max + |aycof| / (am_lo (1 - em_max^2)) = el_max.
//  4. ecose = axnl cos E + aynl sin E, |ecose| <= el for any E (so also for Kepler's
//     equation's last iterate): rl = am (1 - ecose) in [am_lo (1 - el_max), am_hi (1 + el_max)].
//  5. pl = am (1 - el^2) >= am_lo (1 - el_max^2) = pl_lo > 0; temp1 = J2 / (2 pl),
//     temp2 = temp1 / pl, betal = sqrt(1 - el^2) <= 1, |cos 2u| <= 1:
//     mrt = rl (1 - 1.5 temp2 betal con41) + 0.5 temp1 x1mth2 cos 2u lies in
//     [rl_lo (1 - c) - d, rl_hi (1 + c) + d], c = 1.5 |con41| J2 / (2 pl_lo^2),
//     d = 0.25 |x1mth2| J2 / pl_lo (con41, x1mth2 of the epoch inclination: constant in the
//     near-Earth theory).
//  6. |r| = mrt Re |uv| with uv a unit vector (rotation of (cos su, sin su)): the bound times
//     Re, widened by 1e-9 relative for rounding.
// Deep-space element sets add lunar-solar terms to e and i: no bound is claimed for them.
#include <algorithm>
#include <cmath>

#include "evade/sgp4/sgp4.hpp"
#include "interval.hpp"

namespace evade::sgp4 {
using detail::monomial;
using detail::Range;

Sgp4Propagator::MeanRanges Sgp4Propagator::mean_ranges(double t0_min, double t1_min) const noexcept {
  MeanRanges r;
  Range tempa{1.0, 1.0};
  const double coef[4] = {cc1_, isimp_ ? 0.0 : d2_, isimp_ ? 0.0 : d3_, isimp_ ? 0.0 : d4_};
  for (int k = 1; k <= 4; ++k) {
    const Range m = monomial(coef[k - 1], k, t0_min, t1_min);
    tempa = {tempa.lo - m.hi, tempa.hi - m.lo};
  }
  if (!(tempa.lo > 0.0) || !(no_unkozai_ > 0.0)) return r;
  r.am_lo = am_near_ * tempa.lo * tempa.lo;  // am_near_ = (xke / no)^(2/3)
  r.am_hi = am_near_ * tempa.hi * tempa.hi;
  const Range drag = monomial(el_.bstar_per_er * cc4_, 1, t0_min, t1_min);
  const double periodic = isimp_ ? 0.0 : 2.0 * std::abs(el_.bstar_per_er * cc5_);
  r.em_lo = el_.ecco - drag.hi - periodic;
  r.em_hi = el_.ecco - drag.lo + periodic;
  r.ok = true;
  return r;
}

RadiusBounds Sgp4Propagator::radius_bounds(double t0_min, double t1_min) const noexcept {
  RadiusBounds b;
  if (deep_ || init_error_ != Sgp4Error::kNone || !(t0_min <= t1_min)) return b;
  const MeanRanges mr = mean_ranges(t0_min, t1_min);
  if (!mr.ok) return b;
  const Range am{mr.am_lo, mr.am_hi};
  const double em_max = std::max({std::abs(mr.em_lo), std::abs(mr.em_hi), 1e-6});
  if (!(em_max < 1.0)) return b;
  const double el_max = em_max + std::abs(near_.aycof) / (am.lo * (1.0 - em_max * em_max));
  const double pl_lo = am.lo * (1.0 - el_max * el_max);
  if (!(el_max < 1.0) || !(pl_lo > 0.0)) return b;
  const double c = 1.5 * std::abs(near_.con41) * k_.j2 / (2.0 * pl_lo * pl_lo);
  const double d = 0.25 * std::abs(near_.x1mth2) * k_.j2 / pl_lo;
  const double mrt_lo = am.lo * (1.0 - el_max) * (1.0 - c) - d;
  const double mrt_hi = am.hi * (1.0 + el_max) * (1.0 + c) + d;
  const double re_m = k_.radius_km * 1000.0;
  b.bounded = std::isfinite(mrt_lo) && std::isfinite(mrt_hi);
  b.min_m = std::max(0.0, mrt_lo * re_m * (1.0 - 1e-9));
  b.max_m = mrt_hi * re_m * (1.0 + 1e-9);
  return b;
}

}  // namespace evade::sgp4
