// Product quadrature on the unit sphere: Gauss-Legendre in u = cos(theta) on each hemisphere
// (n_u / 2 nodes on [-1, 0] and on [0, 1], so a kink along the equator costs no accuracy)
// times the trapezoid rule in phi (2 n_u equally spaced nodes, exact for trigonometric
// polynomials of degree < 2 n_u). The rule of level L has n_u = 8 * 2^L, L = 0 .. kSphereLevels - 1, so
// each level doubles the resolution in both angles; integrating the same function at
// successive levels estimates the error (the 3D-Nc rate uses this, pc_3d_nc.cpp).
// Gauss-Legendre nodes: Newton's method on the Legendre recurrence (Press et al., Numerical
// Recipes, 3rd ed., sec. 4.6).
#pragma once

#include <vector>

#include "evade/core/state.hpp"

namespace evade::assessment {

inline constexpr int kSphereLevels = 6;

/// Unit vectors (in a local frame whose pole is +z) and weights summing to 4 pi.
struct SphereRule {
  std::vector<Vec3> dir;
  std::vector<double> weight;
};

/// The rule of level 0 <= level < kSphereLevels (built once, thread-safe).
const SphereRule& sphere_rule(int level);

/// n-point Gauss-Legendre nodes and weights on [-1, 1].
void gauss_legendre(int n, std::vector<double>* x, std::vector<double>* w);

}  // namespace evade::assessment
