// The two objects' states at the TCA of a screening event, from the motion the screener used
// (for a CDM: assessment/cdm_from_event.hpp): the motion source when ScreenOptions::motion is
// set (e.g. SGP4, in its frame), else the force model of the options from the objects' states
// at t = 0: two-body by the analytic Kepler propagation, two-body + J2 by DOP853 with
// ScreenOptions::integ from t = 0 straight to the TCA (the screener reached it through its
// grid arcs with the same integrator and tolerances, so the two agree to the integration
// error; robust_screen.hpp). Frame: that of the objects' states (ECI, J2000 axes) or of the
// motion source (MotionSource::frame()).
#pragma once

#include <array>
#include <vector>

#include "evade/conjunction/robust_screen.hpp"
#include "evade/conjunction/types.hpp"

namespace evade::conjunction {

/// States of objects c.i and c.j at c.tca_s. Throws std::invalid_argument for an index out
/// of range, std::runtime_error when the motion is undefined at the TCA.
std::array<StateEci, 2> event_states(const std::vector<SpaceObject>& objects,
                                     const Conjunction& c, const ScreenOptions& opt);

}  // namespace evade::conjunction
