// Monte Carlo Pc with two-body motion (include/evade/assessment/monte_carlo_pc.hpp gives the
// source and the interval).
#include "evade/assessment/monte_carlo_pc.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include <Eigen/Eigenvalues>

#include "evade/dynamics/kepler_propagator.hpp"

namespace evade::assessment {
namespace {

Mat6 square_root(const Mat6& c) {
  Eigen::SelfAdjointEigenSolver<Mat6> es(0.5 * (c + c.transpose()));
  Vec6 s = es.eigenvalues();
  for (int i = 0; i < 6; ++i) s(i) = std::sqrt(std::max(0.0, s(i)));
  return es.eigenvectors() * s.asDiagonal();
}

double distance_at(const KeplerOrbit& a, const KeplerOrbit& b, double t) {
  return (a.state_at(t).r_eci_m - b.state_at(t).r_eci_m).norm();
}

// Closest distance over [-w, w]: grid minimum, then golden section on its two neighbours.
double closest_distance(const KeplerOrbit& a, const KeplerOrbit& b, double w) {
  constexpr int kGrid = 64;
  const double h = 2.0 * w / kGrid;
  int best = 0;
  double best_d = distance_at(a, b, -w);
  for (int i = 1; i <= kGrid; ++i) {
    const double d = distance_at(a, b, -w + i * h);
    if (d < best_d) { best_d = d; best = i; }
  }
  double lo = -w + std::max(0, best - 1) * h;
  double hi = -w + std::min(kGrid, best + 1) * h;
  const double g = 0.5 * (std::sqrt(5.0) - 1.0);
  double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
  double fc = distance_at(a, b, c), fd = distance_at(a, b, d);
  for (int it = 0; it < 60 && hi - lo > 1e-6; ++it) {
    if (fc < fd) { hi = d; d = c; fd = fc; c = hi - g * (hi - lo); fc = distance_at(a, b, c); }
    else { lo = c; c = d; fc = fd; d = lo + g * (hi - lo); fd = distance_at(a, b, d); }
  }
  return std::min(best_d, std::min(fc, fd));
}

}  // namespace

void wilson_interval(long k, long n, double z, double* low, double* high) {
  const double nn = static_cast<double>(n);
  const double p = static_cast<double>(k) / nn;
  const double z2 = z * z;
  const double den = 1.0 + z2 / nn;
  const double centre = (p + z2 / (2.0 * nn)) / den;
  const double half = z * std::sqrt(p * (1.0 - p) / nn + z2 / (4.0 * nn * nn)) / den;
  *low = std::max(0.0, centre - half);
  *high = std::min(1.0, centre + half);
}

MonteCarloResult pc_monte_carlo(const StateEci& obj1, const Mat6& cov1_eci,
                                const StateEci& obj2, const Mat6& cov2_eci, double hbr_m,
                                double mu_m3ps2, const MonteCarloOptions& opt) {
  if (opt.samples < 1) throw std::invalid_argument("Monte Carlo Pc: samples must be >= 1");
  if (!(opt.window_s > 0.0) || !std::isfinite(opt.window_s)) {
    throw std::invalid_argument("Monte Carlo Pc: window_s must be > 0");
  }
  if (!(hbr_m > 0.0)) throw std::invalid_argument("Monte Carlo Pc: hbr_m must be > 0");
  const Mat6 l1 = square_root(cov1_eci);
  const Mat6 l2 = square_root(cov2_eci);
  const Vec6 m1 = obj1.stacked();
  const Vec6 m2 = obj2.stacked();
  std::mt19937_64 rng(opt.seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  MonteCarloResult out;
  out.samples = opt.samples;
  out.window_s = opt.window_s;
  for (long s = 0; s < opt.samples; ++s) {
    Vec6 z1, z2;
    for (int i = 0; i < 6; ++i) z1(i) = normal(rng);
    for (int i = 0; i < 6; ++i) z2(i) = normal(rng);
    const KeplerOrbit a(StateEci::from_stacked(m1 + l1 * z1), mu_m3ps2);
    const KeplerOrbit b(StateEci::from_stacked(m2 + l2 * z2), mu_m3ps2);
    if (closest_distance(a, b, opt.window_s) < hbr_m) ++out.hits;
  }
  out.pc = static_cast<double>(out.hits) / static_cast<double>(out.samples);
  wilson_interval(out.hits, out.samples, opt.z, &out.pc_low, &out.pc_high);
  return out;
}

}  // namespace evade::assessment
