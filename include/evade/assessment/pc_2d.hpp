// Short-term encounter collision probability in the encounter plane (the 2D Pc).
//
// Short-term encounter model (Foster & Estes 1992, NASA JSC-25898; Chan 2008, "Spacecraft
// Collision Probability", ch. 4): at TCA the relative motion is rectilinear, the relative
// position uncertainty is Gaussian, and the velocity uncertainty is negligible, so the Pc is
// the integral of the 2D Gaussian N(0, diag(sx^2, sy^2)) over the hard-body disk of radius R
// centred at the miss (xm, ym), both in the principal axes of the encounter-plane covariance:
//     Pc = (1 / (2 pi sx sy)) \int\int_{(x-xm)^2+(y-ym)^2 <= R^2} exp(-x^2/2sx^2 - y^2/2sy^2).
// pc_2d integrates the y direction in closed form (erfc) and the remaining 1D integral over
// x = xm + R sin(t), t in [-pi/2, pi/2] (which removes the square-root end points) with
// globally adaptive Gauss-Kronrod (7, 15) quadrature (Piessens et al. 1983, QUADPACK QAG),
// split in advance where the integrand turns (x = 0 +- k sx, R cos t = |ym| +- k sy).
// pc_chan: Chan's series (Chan 1997, AAS 97-173; Chan 2008 eq. 5.33) with u = R^2/(sx sy),
//     v = xm^2/sx^2 + ym^2/sy^2,  Pc = e^{-v/2} sum_m (v/2)^m/m! (1 - e^{-u/2} sum_{k<=m} (u/2)^k/k!).
// pc_max_alfano: the largest Pc over a common scale k of the covariance (Alfano 2005,
// "Relating Position Uncertainty to Maximum Conjunction Probability", J. Astronaut. Sci. 53),
// found by golden-section search on log k with pc_2d.
//
// One implementation serves the ground and the node (docs/AUTONOMY.md AUT-4): the quadrature
// runs on a caller's Pc2dWorkspace (a fixed heap of at most kMaxPanels panels, the same
// push_heap/pop_heap refinement order as a priority queue) and reports bad input as a status,
// with no allocation and no exception; the ground's pc_2d() is that computation on a workspace
// of its own, throwing std::invalid_argument for bad input.
#pragma once

#include <array>
#include <cstdint>

namespace evade::assessment {

/// The encounter in the principal axes of its 2D covariance [m].
struct PrincipalEncounter {
  double miss_x_m = 0.0;
  double miss_y_m = 0.0;
  double sigma_x_m = 0.0;
  double sigma_y_m = 0.0;
};

struct Pc2dResult {
  double pc = 0.0;
  double abs_error = 0.0;  ///< quadrature error estimate (|K15 - G7| summed over panels)
  int panels = 0;          ///< panels used by the adaptive quadrature
};

enum class Pc2dStatus : std::uint8_t {
  kOk = 0,
  kNotFinite,     ///< a miss, a sigma or the hard-body radius is NaN or Inf
  kBadSigma,      ///< a sigma is not > 0
  kBadHbr,        ///< the hard-body radius is not > 0
  kBadTolerance,  ///< rel_tol is not > 0
};
const char* pc_2d_status_name(Pc2dStatus s) noexcept;

/// One panel of the adaptive quadrature.
struct Pc2dPanel {
  double a = 0.0, b = 0.0, value = 0.0, error = 0.0;
  bool operator<(const Pc2dPanel& o) const noexcept { return error < o.error; }
};
/// The quadrature's memory (16 KiB): preallocate one where nothing may allocate.
struct Pc2dWorkspace {
  /// Panels at most: the encounters of the test suite take up to 138 (Alfano 2009 and CARA's
  /// cases take under 40); past it the result stands with its error estimate (abs_error).
  static constexpr int kMaxPanels = 512;
  std::array<Pc2dPanel, kMaxPanels> panels{};
};

/// The 2D Pc into *out, on *ws (flight code: no allocation, no exception). kOk, or the first
/// problem of the input (then *out is zero).
Pc2dStatus pc_2d(const PrincipalEncounter& e, double hbr_m, double rel_tol, Pc2dWorkspace* ws,
                 Pc2dResult* out) noexcept;
/// The same on a workspace of its own. Throws std::invalid_argument for a non-finite input,
/// sigma <= 0 or hbr <= 0.
Pc2dResult pc_2d(const PrincipalEncounter& e, double hbr_m, double rel_tol = 1e-8);
/// Chan's series, summed until its terms no longer change the sum.
double pc_chan(const PrincipalEncounter& e, double hbr_m);

struct PcMaxResult {
  double pc_max = 0.0;
  double scale = 1.0;  ///< covariance scale k (sigma -> k sigma) at the maximum
};
/// Alfano's maximum Pc over the covariance scale k in [1e-4, 1e4].
PcMaxResult pc_max_alfano(const PrincipalEncounter& e, double hbr_m);

}  // namespace evade::assessment
