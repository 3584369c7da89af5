// The time integral of the 3D-Nc collision rate (step 5 of the method): Gauss-Kronrod (7, 15)
// panels, the worst one halved until the error estimate reaches rel_tol.
// 3D-Nc collision probability (D. T. Hall, "Expected collision rates for tracked satellites",
// J. Spacecraft and Rockets 58(3), 2021, "H21"; the notation follows NASA CARA's Pc3D_Hall,
// whose published results the tests reproduce).
//   5. Nc = \int dNc/dt dt over the window by globally adaptive Gauss-Kronrod (7, 15)
//      quadrature (Piessens et al. 1983, QUADPACK QAG and its error estimate) to rel_tol, from
//      panels that resolve Coppola's window and cover the rest uniformly. The window is
//      [-window_s, window_s], or (window_s = 0) Coppola's bounds (AAS 12-248 eqs. 12-16) for
//      gamma, clipped to half the shorter period and widened while the rate at an end exceeds
//      2.5e-6 of the peak (CARA's refinement cut, gamma = 1e-6). For one isolated conjunction
//      Nc is the Pc (H21); pc is clipped to 1 as CARA does for quadrature error.
#include "nc_time_integral.hpp"

#include <algorithm>
#include <cmath>

#include "evade/core/gauss_kronrod.hpp"

namespace evade::assessment::nc {

double TimeIntegral::rate_at(double t_s, double* small_per_s) {
  const nc::Rate r = nc::collision_rate(p1_, p2_, t_s, rs_, 1e-2 * opt_.rel_tol * peak_);
  ++evaluations_;
  if (r.rate_per_s > peak_) {
    peak_ = r.rate_per_s;
    t_peak_ = t_s;
  }
  if (!r.pop_converged) worst_pop_failure_ = std::max(worst_pop_failure_, r.rate_per_s);
  if (!r.sphere_converged) worst_sphere_error_ = std::max(worst_sphere_error_, r.sphere_error_per_s);
  if (small_per_s != nullptr) *small_per_s = r.rate_small_per_s;
  return r.rate_per_s;
}

NcPanel TimeIntegral::evaluate(double a, double b) {
  const double c = 0.5 * (a + b), h = 0.5 * (b - a);
  double f[15], fs[15];
  for (int k = 0; k < 7; ++k) {
    f[k] = rate_at(c - h * kGk15Nodes[k], &fs[k]);
    f[14 - k] = rate_at(c + h * kGk15Nodes[k], &fs[14 - k]);
  }
  f[7] = rate_at(c, &fs[7]);
  NcPanel p{a, b, 0.0, 0.0, 0.0};
  double gauss = kG7Weights[3] * f[7];
  for (int k = 0; k < 8; ++k) {
    const double sym = k < 7 ? f[k] + f[14 - k] : f[7];
    p.nc += kGk15Weights[k] * sym;
    p.nc_small += kGk15Weights[k] * (k < 7 ? fs[k] + fs[14 - k] : fs[7]);
    if (k % 2 == 1 && k < 7) gauss += kG7Weights[k / 2] * sym;
  }
  const double mean = 0.5 * p.nc;
  double resasc = 0.0;
  for (int k = 0; k < 15; ++k) resasc += kGk15Weights[k < 8 ? k : 14 - k] * std::abs(f[k] - mean);
  p.nc *= h;
  p.nc_small *= h;
  resasc *= h;
  p.err = std::abs(p.nc - gauss * h);
  if (resasc > 0.0 && p.err > 0.0) p.err = resasc * std::min(1.0, std::pow(200.0 * p.err / resasc, 1.5));
  return p;
}

void TimeIntegral::add_panels(double a, double b, int count) {
  const double w = (b - a) / count;
  for (int i = 0; i < count && budget_left(); ++i) {
    panels_.push_back(evaluate(a + i * w, i + 1 == count ? b : a + (i + 1) * w));
  }
}

double TimeIntegral::total(double NcPanel::*field) const {
  double s = 0.0;
  for (const NcPanel& p : panels_) s += p.*field;
  return s;
}

void TimeIntegral::refine() {
  while (budget_left()) {
    const double nc = total(&NcPanel::nc);
    if (total(&NcPanel::err) <= opt_.rel_tol * std::abs(nc) + 1e-300) return;
    const auto worst = std::max_element(panels_.begin(), panels_.end(),
        [](const NcPanel& x, const NcPanel& y) { return x.err < y.err; });
    const double a = worst->a, b = worst->b, m = 0.5 * (a + b);
    panels_.erase(worst);
    panels_.push_back(evaluate(a, m));
    panels_.push_back(evaluate(m, b));
  }
}

}  // namespace evade::assessment::nc
