// Interval arithmetic for the SGP4 bounds (radius_bounds.cpp, path_bounds.cpp): ranges of
// monomials, products, cosines and sines over intervals, each exact up to rounding (the
// callers widen their results for it).
#pragma once

#include <algorithm>
#include <cmath>

namespace evade::sgp4::detail {

struct Range {
  double lo, hi;
};

// The range of c t^k over t in [t0, t1] (t0 <= t1).
inline Range monomial(double c, int k, double t0, double t1) {
  const double a = std::pow(t0, k), b = std::pow(t1, k);
  double lo = std::min(a, b), hi = std::max(a, b);
  if (k % 2 == 0 && t0 < 0.0 && t1 > 0.0) lo = 0.0;
  return c >= 0.0 ? Range{c * lo, c * hi} : Range{c * hi, c * lo};
}

inline Range add(Range a, Range b) { return {a.lo + b.lo, a.hi + b.hi}; }

inline Range times(Range a, Range b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  return {std::min({p[0], p[1], p[2], p[3]}), std::max({p[0], p[1], p[2], p[3]})};
}

inline Range scale(double c, Range a) { return c >= 0.0 ? Range{c * a.lo, c * a.hi} : Range{c * a.hi, c * a.lo}; }

// The range of cos x over x in [a, b] (a <= b): the end values, 1 where the interval holds a
// multiple of 2 pi, -1 where it holds an odd multiple of pi.
inline Range cos_range(double a, double b) {
  constexpr double kTwoPi = 6.283185307179586;
  constexpr double kPi = 3.141592653589793;
  if (!(b - a < kTwoPi)) return {-1.0, 1.0};
  Range r{std::min(std::cos(a), std::cos(b)), std::max(std::cos(a), std::cos(b))};
  if (std::ceil(a / kTwoPi) * kTwoPi <= b) r.hi = 1.0;
  if (std::ceil((a - kPi) / kTwoPi) * kTwoPi + kPi <= b) r.lo = -1.0;
  return r;
}

inline Range sin_range(double a, double b) {
  constexpr double kHalfPi = 1.5707963267948966;
  return cos_range(a - kHalfPi, b - kHalfPi);
}

}  // namespace evade::sgp4::detail
