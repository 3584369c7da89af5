// State and covariance propagation for assessment: two-body + J2 (dynamics::propagate_orbit,
// DOP853 with tight tolerances), and the linear covariance map P(t) = Phi P(t0) Phi^T with
// the state transition matrix Phi of the same model by central differences
// (Phi e_j = (x(t; x0 + h_j e_j) - x(t; x0 - h_j e_j)) / 2 h_j, h = 1 m and 1 mm/s), the
// first-order covariance propagation of Vallado 4th ed. sec. 10.7 / Tapley, Schutz & Born
// 2004 sec. 4.4.
#pragma once

#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

StateEci propagate_j2(const StateEci& s, double dt_s, const EarthModel& earth);
Mat6 state_transition_j2(const StateEci& s, double dt_s, const EarthModel& earth);
Mat6 propagate_covariance_j2(const StateEci& s, const Mat6& cov, double dt_s,
                             const EarthModel& earth);

}  // namespace evade::assessment
