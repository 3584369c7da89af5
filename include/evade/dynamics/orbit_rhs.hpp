// The orbit equation's right-hand side d/dt [r; v] = [v; a(r)] as a function object, for
// integrators that take their right-hand side by type (Dop853<Vec6, OrbitRhs>).
//
// a(r): point mass, Vallado, Fundamentals of Astrodynamics and Applications, 4th ed.,
// eq. 1-14, plus (two-body + J2) the J2 term of eq. 8-30. The operations are those of
// orbit_derivative (gravity.cpp) in the same order, so an integration with OrbitRhs takes
// bit for bit the same steps as one with orbit_derivative behind a std::function; it is only
// inlined, and copying the integrator allocates nothing (test: orbit_rhs_test).
#pragma once

#include <cmath>

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"
#include "evade/dynamics/gravity.hpp"

namespace evade {

struct OrbitRhs {
  GravityModel model = GravityModel::kTwoBodyJ2;
  EarthModel earth = kEarthDefault;

  Vec6 operator()(double /*t_s*/, const Vec6& x) const {
    const Vec3 r = x.head<3>();
    const double r2 = r.squaredNorm();
    const double rn = std::sqrt(r2);
    const double c = -earth.mu_m3ps2 / (r2 * rn);  // eq. 1-14
    double ax = c * r.x();
    double ay = c * r.y();
    double az = c * r.z();
    if (model == GravityModel::kTwoBodyJ2) {  // eq. 8-30
      const double z2_over_r2 = r.z() * r.z() / r2;
      const double k = -1.5 * earth.j2 * earth.mu_m3ps2 * earth.re_m * earth.re_m / (r2 * r2 * rn);
      const double xy = 1.0 - 5.0 * z2_over_r2;
      ax += k * r.x() * xy;
      ay += k * r.y() * xy;
      az += k * r.z() * (3.0 - 5.0 * z2_over_r2);
    }
    Vec6 d;
    d << x[3], x[4], x[5], ax, ay, az;
    return d;
  }
};

}  // namespace evade
