// The old home of the avoidance manoeuvre as a BurnPlan, kept for the test of test/lcm_link
// that still includes it and calls assessment::make_cam_burn_plan (issue 41 moved it to
// evade/cam/cam_burn_plan.hpp, evade::cam). Only that test sees this folder
// (test/CMakeLists.txt); delete it once the test includes the cam header.
#pragma once

#include "evade/cam/cam_burn_plan.hpp"
#include "evade/assessment/cam_planner.hpp"

namespace evade::assessment {
using cam::make_cam_burn_plan;
}  // namespace evade::assessment
