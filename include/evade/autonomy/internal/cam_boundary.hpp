// The boundary solve of the onboard avoidance burn (onboard_cam.hpp, step 2), for
// src/autonomy/onboard_cam.cpp: the smallest burn of one linear model, and the along-track
// starts. Flight code: no allocation, no exceptions, loops bounded by the options' counts.
#pragma once

#include "evade/autonomy/onboard_cam.hpp"

namespace evade::autonomy {

/// The smallest burn of the model about `ref` (made with dv_ref) reaching Pc <= aim.
CamStatus solve_model(const ConjunctionEvent& e, const BurnOutcome& ref, const Vec3& dv_ref, double aim,
                      const OnboardCamOptions& o, CamWorkspace* ws, Vec3* dv) noexcept;

/// The smallest along-track burn of sign `sign` of the model about no burn reaching the aim
/// (zero when that side needs more than max_dv_mps).
Vec3 along_track_start(const ConjunctionEvent& e, const BurnOutcome& ref, const Vec6& x_burn, double aim,
                       double sign, const OnboardCamOptions& o, CamWorkspace* ws) noexcept;

}  // namespace evade::autonomy
