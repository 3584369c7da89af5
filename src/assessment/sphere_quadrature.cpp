// Unit-sphere product quadrature (include/evade/assessment/sphere_quadrature.hpp).
#include "evade/assessment/sphere_quadrature.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

namespace evade::assessment {
namespace {

constexpr double kPi = 3.14159265358979323846;

SphereRule build_rule(int level) {
  const int nu = 8 << level;
  const int nphi = 2 * nu;
  // Gauss-Legendre on each hemisphere, u in [-1, 0] and [0, 1]: the flux integrand has a kink
  // on the great circle normal to the relative velocity, which the caller puts at u = 0.
  std::vector<double> g, wg;
  gauss_legendre(nu / 2, &g, &wg);
  std::vector<double> u, wu;
  for (double sign : {-1.0, 1.0}) {
    for (std::size_t i = 0; i < g.size(); ++i) {
      u.push_back(0.5 * (sign + g[i]));
      wu.push_back(0.5 * wg[i]);
    }
  }
  SphereRule s;
  s.dir.reserve(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nphi));
  s.weight.reserve(static_cast<std::size_t>(nu) * static_cast<std::size_t>(nphi));
  const double dphi = 2.0 * kPi / nphi;
  for (int i = 0; i < nu; ++i) {
    const double st = std::sqrt(std::max(0.0, 1.0 - u[i] * u[i]));
    for (int k = 0; k < nphi; ++k) {
      const double phi = (k + 0.5) * dphi;
      s.dir.emplace_back(st * std::cos(phi), st * std::sin(phi), u[i]);
      s.weight.push_back(wu[i] * dphi);
    }
  }
  return s;
}

std::array<SphereRule, kSphereLevels> build_all() {
  std::array<SphereRule, kSphereLevels> all;
  for (int l = 0; l < kSphereLevels; ++l) all[l] = build_rule(l);
  return all;
}

}  // namespace

void gauss_legendre(int n, std::vector<double>* x, std::vector<double>* w) {
  x->assign(static_cast<std::size_t>(n), 0.0);
  w->assign(static_cast<std::size_t>(n), 0.0);
  for (int i = 0; i < (n + 1) / 2; ++i) {
    double z = std::cos(kPi * (i + 0.75) / (n + 0.5));
    double dp = 1.0;
    for (int it = 0; it < 100; ++it) {
      double p0 = 1.0, p1 = z;
      for (int k = 2; k <= n; ++k) {
        const double p2 = ((2.0 * k - 1.0) * z * p1 - (k - 1.0) * p0) / k;
        p0 = p1;
        p1 = p2;
      }
      dp = n * (z * p1 - p0) / (z * z - 1.0);
      const double dz = p1 / dp;
      z -= dz;
      if (std::abs(dz) < 1e-16) break;
    }
    (*x)[static_cast<std::size_t>(i)] = -z;
    (*x)[static_cast<std::size_t>(n - 1 - i)] = z;
    const double wi = 2.0 / ((1.0 - z * z) * dp * dp);
    (*w)[static_cast<std::size_t>(i)] = wi;
    (*w)[static_cast<std::size_t>(n - 1 - i)] = wi;
  }
}

const SphereRule& sphere_rule(int level) {
  if (level < 0 || level >= kSphereLevels) throw std::out_of_range("sphere_rule: bad level");
  static const std::array<SphereRule, kSphereLevels> all = build_all();
  return all[static_cast<std::size_t>(level)];
}

}  // namespace evade::assessment
