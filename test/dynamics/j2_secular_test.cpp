// Numerically propagated J2 orbit: secular drift of RAAN and argument of perigee against
// the analytic first-order rates (Vallado eq. 9-41, 9-42).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "evade/core/elements.hpp"
#include "evade/dynamics/gravity.hpp"
#include "evade/dynamics/orbit_propagator.hpp"
#include "test_orbits.hpp"

namespace evade {
namespace {

struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
};

LineFit fit_line(const std::vector<double>& t, const std::vector<double>& y) {
  double st = 0, sy = 0, stt = 0, sty = 0;
  const double n = static_cast<double>(t.size());
  for (std::size_t k = 0; k < t.size(); ++k) {
    st += t[k];
    sy += y[k];
    stt += t[k] * t[k];
    sty += t[k] * y[k];
  }
  LineFit f;
  f.slope = (n * sty - st * sy) / (n * stt - st * st);
  f.intercept = (sy - f.slope * st) / n;
  return f;
}

// Osculating elements oscillate at the orbital period with O(J2) amplitude (for argp,
// O(J2/e) ~ 0.1 rad at e = 0.01); mean elements are their orbit average to first order in
// J2. A least-squares line over 10 days (~150 orbits, 60 s samples) averages the periodic
// terms: their residual slope is ~ amplitude / (T * number of orbits) ~ 1e-9 rad/s * 1e-2,
// i.e. < 0.1% of the rates. The analytic rates are first order in J2; second-order terms
// are ~J2 ~ 0.1% of them. Hence the 1% requirement has a 10x margin. The rates are
// evaluated at the averaged osculating a, e, i (= mean elements to first order).
TEST(J2Secular, RaanAndPerigeeDriftMatchAnalyticRatesOverTenDays) {
  const EarthModel earth = kEarthDefault;
  const double a0 = 7000e3;
  const StateEci s0 =
      test::orbit_state(a0, 0.01, 50.0 * kDegToRad, 30.0 * kDegToRad, 40.0 * kDegToRad, 0.0);
  const double span_s = 10.0 * kSecondsPerDay;
  std::vector<double> t;
  for (double tk = 0.0; tk <= span_s; tk += 60.0) t.push_back(tk);
  const std::vector<StateEci> states =
      propagate_orbit_samples(s0, t, GravityModel::kTwoBodyJ2, earth);

  std::vector<double> raan, argp;
  double a_sum = 0, e_sum = 0, i_sum = 0;
  for (std::size_t k = 0; k < states.size(); ++k) {
    const OrbitalElements oe = elements_from_state(states[k], earth.mu_m3ps2);
    double r = oe.raan_rad;
    double w = oe.argp_rad;
    if (k > 0) {  // unwrap onto a continuous branch
      r = raan.back() + wrap_pi(r - raan.back());
      w = argp.back() + wrap_pi(w - argp.back());
    }
    raan.push_back(r);
    argp.push_back(w);
    a_sum += oe.a_m;
    e_sum += oe.e;
    i_sum += oe.i_rad;
  }
  const double n = static_cast<double>(states.size());
  const J2SecularRates rates = j2_secular_rates(a_sum / n, e_sum / n, i_sum / n, earth);
  const double raan_dot = fit_line(t, raan).slope;
  const double argp_dot = fit_line(t, argp).slope;
  std::printf("RAAN rate: numeric %.6e, analytic %.6e rad/s (rel diff %.2e)\n", raan_dot,
              rates.raan_dot_radps, raan_dot / rates.raan_dot_radps - 1.0);
  std::printf("argp rate: numeric %.6e, analytic %.6e rad/s (rel diff %.2e)\n", argp_dot,
              rates.argp_dot_radps, argp_dot / rates.argp_dot_radps - 1.0);
  // Drift must be clearly measurable: > 0.5 rad over 10 days for both angles.
  ASSERT_GT(std::abs(rates.raan_dot_radps) * span_s, 0.5);
  ASSERT_GT(std::abs(rates.argp_dot_radps) * span_s, 0.5);
  EXPECT_NEAR(raan_dot / rates.raan_dot_radps, 1.0, 0.01);
  EXPECT_NEAR(argp_dot / rates.argp_dot_radps, 1.0, 0.01);
}

// Without J2 the same numerical path must show no drift (sanity of the measurement).
TEST(J2Secular, TwoBodyNumericalOrbitHasNoNodalDrift) {
  const StateEci s0 =
      test::orbit_state(7000e3, 0.01, 50.0 * kDegToRad, 30.0 * kDegToRad, 40.0 * kDegToRad, 0.0);
  // Force the numerical path by integrating with J2 = 0.
  EarthModel no_j2 = kEarthDefault;
  no_j2.j2 = 0.0;
  const StateEci s1 =
      propagate_orbit(s0, 10.0 * kSecondsPerDay, GravityModel::kTwoBodyJ2, no_j2);
  const OrbitalElements e0 = elements_from_state(s0, no_j2.mu_m3ps2);
  const OrbitalElements e1 = elements_from_state(s1, no_j2.mu_m3ps2);
  // Default tolerance: position error < 1 m/day -> node error << 1e-6 rad.
  EXPECT_NEAR(wrap_pi(e1.raan_rad - e0.raan_rad), 0.0, 1e-6);
}

}  // namespace
}  // namespace evade
