// Bounds of the SGP4 path over an interval of time, from the near-Earth theory's formulas
// (Vallado, Crawford, Hujsak & Kelso 2006, "Revisiting Spacetrack Report #3"; sgp4.cpp), for
// the orbit-path filter of catalog screening (the second of Hoots, Crawford & Roehrich's
// filters, "An analytic method to determine future close approaches between satellites",
// Celestial Mechanics 33, 1984; conjunction/primary_path_filter.hpp uses them).
//
// Argument, t in [t0, t1] (minutes from the epoch), the names of propagate_min and the
// ranges of am, em, el and pl of radius_bounds.cpp:
//  1. Direction. propagate_min returns mrt Re uv with uv = cos su N + sin su M, N and M the
//     node and in-plane unit vectors of (xnode, xinc); xnode = nodem + 1.5 temp2 cos i sin 2u,
//     nodem = nodeo + nodedot t + nodecf t^2 (each monomial's range exact), xinc = inclo +
//     1.5 temp2 cos i sin i cos 2u, su = u - 0.25 temp2 x7thm1 sin 2u, with
//     temp2 = J2 / (2 pl^2) <= J2 / (2 pl_lo^2): node, inclination and |su - u| in the
//     ranges stored.
//  2. Radius against direction. With the Lyddane elements (axnl, aynl) =
//     (em cos argpm, em sin argpm + y), y = aycof / (am (1 - em^2)), and any (cos F, sin F)
//     (Kepler's last iterate), rl = am (1 - ecose) and (cos u, sin u) are the focus distance
//     and direction of the point of eccentric longitude F on the ellipse of semi-major axis
//     am and eccentricity vector (axnl, aynl), so rl = pl / (1 + axnl cos u + aynl sin u)
//     = pl / q, q = 1 + em cos(u - argpm) + y sin u (checked against SGP4's rl in
//     path_bounds_test.cpp). argpm = argpo + (argpdot - omgcof) t - delm, |delm| bounded by
//     xmcof ((1 +- eta)^3 - delmo) (delmtemp = 1 + eta cos M in [1 - eta, 1 + eta]); em, am
//     as radius_bounds. Over u in an arc the cosine's and sine's ranges are exact, q's by
//     interval arithmetic; q_lo <= 0 gives no tighter bound than radius_bounds'.
//  3. mrt = rl (1 - 0.75 J2 con41 betal / pl^2) + 0.25 J2 x1mth2 cos 2u / pl: interval
//     products over betal = sqrt(1 - el^2), pl and cos 2u (u in the arc widened by |su - u|).
//  4. The bound times Re, widened by 1e-9 relative for rounding (as radius_bounds), and
//     intersected with radius_bounds' (both hold).
#include <algorithm>
#include <cmath>

#include "evade/sgp4/sgp4.hpp"
#include "interval.hpp"

namespace evade::sgp4 {
using detail::add;
using detail::monomial;
using detail::Range;
using detail::scale;
using detail::times;

PathBounds Sgp4Propagator::path_bounds(double t0_min, double t1_min) const noexcept {
  PathBounds b;
  b.radius = radius_bounds(t0_min, t1_min);
  if (!b.radius.bounded) return b;  // also deep space, init errors and t0 > t1
  const MeanRanges mr = mean_ranges(t0_min, t1_min);  // ok: radius_bounds' own call held
  b.am_lo = mr.am_lo;
  b.am_hi = mr.am_hi;
  b.em_lo = std::max(1e-6, mr.em_lo);  // the theory's clamp
  b.em_hi = std::max(1e-6, mr.em_hi);
  Range argp = add({el_.argpo_rad, el_.argpo_rad},
                   monomial(ep_.argpdot - (isimp_ ? 0.0 : omgcof_), 1, t0_min, t1_min));
  if (!isimp_) {
    const double e = std::abs(eta_);
    const Range cube{std::pow(1.0 - e, 3) - delmo_, std::pow(1.0 + e, 3) - delmo_};
    const Range delm = scale(xmcof_, cube);
    argp = {argp.lo - delm.hi, argp.hi - delm.lo};
  }
  b.argp_lo_rad = argp.lo;
  b.argp_hi_rad = argp.hi;
  const Range inv{1.0 / (b.am_hi * (1.0 - b.em_lo * b.em_lo)), 1.0 / (b.am_lo * (1.0 - b.em_hi * b.em_hi))};
  const Range y = scale(near_.aycof, inv);
  b.y_lo = y.lo;
  b.y_hi = y.hi;
  const double el_max = b.em_hi + std::max(std::abs(y.lo), std::abs(y.hi));
  const double pl_lo = b.am_lo * (1.0 - el_max * el_max);
  if (!(el_max < 1.0) || !(pl_lo > 0.0) || !(b.em_hi < 1.0)) return b;
  const double temp2_max = 0.5 * k_.j2 / (pl_lo * pl_lo);
  const Range node = add({el_.nodeo_rad, el_.nodeo_rad},
                         add(monomial(ep_.nodedot, 1, t0_min, t1_min), monomial(nodecf_, 2, t0_min, t1_min)));
  const double dnode = 1.5 * temp2_max * std::abs(cos_inclo_);
  const double dinc = 1.5 * temp2_max * std::abs(cos_inclo_ * sin_inclo_);
  b.node_lo_rad = node.lo - dnode;
  b.node_hi_rad = node.hi + dnode;
  b.incl_lo_rad = el_.inclo_rad - dinc;
  b.incl_hi_rad = el_.inclo_rad + dinc;
  b.du_rad = 0.25 * temp2_max * std::abs(near_.x7thm1);
  b.con41 = near_.con41;
  b.x1mth2 = near_.x1mth2;
  b.j2 = k_.j2;
  b.re_m = k_.radius_km * 1000.0;
  b.bounded = std::isfinite(b.node_lo_rad + b.node_hi_rad + b.argp_lo_rad + b.argp_hi_rad + b.du_rad);
  return b;
}

RadiusBounds path_radius_in_arc(const PathBounds& b, double s_lo_rad, double s_hi_rad) noexcept {
  if (!b.bounded || !(s_lo_rad <= s_hi_rad)) return b.radius;
  const double u_lo = s_lo_rad - b.du_rad, u_hi = s_hi_rad + b.du_rad;
  const Range c = detail::cos_range(u_lo - b.argp_hi_rad, u_hi - b.argp_lo_rad);
  const Range q = add({1.0, 1.0}, add(times({b.em_lo, b.em_hi}, c),
                                      times({b.y_lo, b.y_hi}, detail::sin_range(u_lo, u_hi))));
  if (!(q.lo > 0.0)) return b.radius;
  const double y_max = std::max(std::abs(b.y_lo), std::abs(b.y_hi));
  const double el2_hi = (b.em_hi + y_max) * (b.em_hi + y_max);
  const double el2_lo = std::pow(std::max(0.0, b.em_lo - y_max), 2);
  const Range pl{b.am_lo * (1.0 - el2_hi), b.am_hi * (1.0 - el2_lo)};
  const Range rl{pl.lo / q.hi, pl.hi / q.lo};
  const Range bp{std::sqrt(1.0 - el2_hi) / (pl.hi * pl.hi), std::sqrt(1.0 - el2_lo) / (pl.lo * pl.lo)};
  const Range f = add({1.0, 1.0}, scale(-0.75 * b.j2 * b.con41, bp));
  const Range g = scale(0.25 * b.j2 * b.x1mth2,
                        times(detail::cos_range(2.0 * u_lo, 2.0 * u_hi), {1.0 / pl.hi, 1.0 / pl.lo}));
  RadiusBounds r;
  r.bounded = true;
  r.min_m = std::max(b.radius.min_m, (rl.lo * f.lo + g.lo) * b.re_m * (1.0 - 1e-9));
  r.max_m = std::min(b.radius.max_m, (rl.hi * f.hi + g.hi) * b.re_m * (1.0 + 1e-9));
  return r;
}

}  // namespace evade::sgp4
