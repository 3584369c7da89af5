// The old home of the avoidance-manoeuvre planner, kept for the test of test/lcm_link that
// still includes it and calls assessment::plan_cam (issue 41 moved the planner to its own
// module: evade/cam/cam_planner.hpp, evade::cam). Only that test sees this folder
// (test/CMakeLists.txt); delete it once the test includes the cam header.
#pragma once

#include "evade/cam/cam_planner.hpp"

namespace evade::assessment {
using cam::CamConfig;
using cam::CamPlan;
using cam::CamRequest;
using cam::plan_cam;
}  // namespace evade::assessment
