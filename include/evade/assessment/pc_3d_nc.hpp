// 3D-Nc collision probability: the expected number of collisions of one conjunction, from
// both objects' 6x6 states and covariances, with two-body (curved) motion.
//
// D. T. Hall, "Expected collision rates for tracked satellites", Journal of Spacecraft and
// Rockets 58(3), 2021. (Equation numbers and the steps are in pc_3d_nc.cpp's header.)
// V. T. Coppola, "Evaluating the short encounter assumption of the probability of collision
// formula", AAS 12-248, 2012: the conjunction-duration bounds used as the default window.
#pragma once

#include <string>

#include "evade/core/state.hpp"

namespace evade::assessment {

struct Nc3dOptions {
  double window_s = 0.0;       ///< > 0: integrate over [-window_s, +window_s] about TCA [s];
                               ///< 0: the window from Coppola's bounds (gamma below)
  double gamma = 1e-16;        ///< Coppola's bound: probability left outside the window [-]
  double rel_tol = 1e-4;       ///< relative accuracy of the time integral of the rate [-]
  double sphere_rel_tol = 1e-6;  ///< relative accuracy of each unit-sphere integral [-]
  int max_rate_evaluations = 20000;  ///< bound on the work; not converged beyond it
};

/// Conjunction-duration bounds about TCA (Coppola 2012): [tau0_s, tau1_s], tau0 < 0 < tau1
/// for a crossing encounter; infinite when the relative velocity is zero.
struct EncounterWindow {
  double tau0_s = 0.0;
  double tau1_s = 0.0;
};

struct Nc3dResult {
  double pc = 0.0;              ///< Nc over the window (= Pc for one isolated conjunction) [-]
  double pc_small_hbr = 0.0;    ///< Nc in the small-HBR limit (rate at the sphere centre) [-]
  double t_begin_s = 0.0;       ///< integration window about TCA [s]
  double t_end_s = 0.0;
  double t_peak_s = 0.0;        ///< time of the largest collision rate, about TCA [s]
  double conj_begin_s = 0.0;    ///< the span holding all but 5e-7 of Nc on each side [s]
  double conj_end_s = 0.0;      ///< (CARA's TaConj, TbConj)
  double rate_peak_per_s = 0.0; ///< the largest collision rate dNc/dt [1/s]
  EncounterWindow coppola;      ///< Coppola's bounds for opt.gamma (also when window_s > 0)
  double period1_s = 0.0;       ///< two-body orbital periods [s]
  double period2_s = 0.0;
  int rate_evaluations = 0;     ///< number of times the collision rate was evaluated
  bool converged = false;       ///< integral met rel_tol and every rate evaluation converged
  std::string failure;          ///< why not converged (empty when converged)
};

/// The 3D-Nc Pc of two objects with states and 6x6 ECI covariances [m^2, m^2/s, m^2/s^2]
/// at (or near) TCA, combined hard-body radius hbr_m, gravitational parameter mu_m3ps2.
/// Throws std::invalid_argument for non-finite input, hbr_m <= 0, a covariance that is not
/// symmetric positive semi-definite (its correlation matrix's smallest eigenvalue below
/// -1e-4; a slightly NPD one, like Alfano case 06's, is used as given, as CARA does), or an
/// unbound (e >= 1) orbit. pc is NaN (converged false) if the equinoctial elements stay
/// undefined after the retrograde reorientation.
Nc3dResult pc_3d_nc(const StateEci& obj1, const Mat6& cov1_eci, const StateEci& obj2,
                    const Mat6& cov2_eci, double hbr_m, double mu_m3ps2,
                    const Nc3dOptions& opt = Nc3dOptions{});

/// Coppola's conjunction-duration bounds for probability gamma (linear relative motion, the
/// combined 6x6 covariance): the times about TCA outside which the probability of a
/// hard-body overlap is below gamma.
EncounterWindow coppola_window(const StateEci& obj1, const Mat6& cov1_eci,
                               const StateEci& obj2, const Mat6& cov2_eci, double hbr_m,
                               double gamma);

}  // namespace evade::assessment
