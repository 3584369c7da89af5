// Parameters of the collision-avoidance-manoeuvre planner (key prefix "cam."), read with
// config::read_params; the one place their ranges live (cam_planner.hpp uses them).
#pragma once

#include "evade/core/param.hpp"

namespace evade::cam {

struct CamConfig {
  double max_dv_mps = 1.0;          ///< largest |dv| the planner may use [m/s]
  double max_lead_s = 259200.0;     ///< longest lead (burn before TCA) [s]: 3 days
  double pc_margin = 1e-3;          ///< the planner aims at pc_max (1 - margin)
  double miss_margin_m = 0.01;      ///< and at min_miss_m + this [m]
  int boundary_angles = 360;        ///< directions of the encounter-plane boundary sweep
  int max_relinearizations = 8;     ///< model re-linearizations about the burned trajectory
  double dv_tol_mps = 1e-6;         ///< convergence of the re-linearization [m/s]
  int max_target_corrections = 6;   ///< re-plans when the recommended Pc misses pc_max
};

ParamTable<CamConfig> cam_params() noexcept;

}  // namespace evade::cam
