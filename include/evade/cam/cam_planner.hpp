// Collision-avoidance manoeuvre (CAM) planner: the smallest impulsive burn of the primary,
// made lead_s before TCA, after which the 2D Pc is below pc_max and the miss distance above
// min_miss_m.
//
// Problem: minimise |dv| over dv in the primary's RTN frame (or dv = (0, dv_T, 0) with
// along_track_only) subject to Pc(dv) <= pc_max (1 - cam.pc_margin) and
// miss(dv) >= min_miss_m + cam.miss_margin_m, |dv| <= cam.max_dv_mps. Method, on the linear model of cam_encounter.hpp:
//  1. Encounter-plane reduction. With the encounter plane held fixed, a burn moves the miss
//     point linearly, m(dv) = m0 + A dv (A = -[x^T; z^T] dr/ddv, 2x3), and the minimum-norm
//     burn reaching a point m is dv = A^+ (m - m0), |dv|^2 = (m - m0)^T (A A^T)^-1 (m - m0).
//     Pc as a function of the miss point is a Gaussian convolved with the hard-body disk,
//     symmetric and log-concave (Prekopa 1973: convolution preserves log-concavity), so the
//     region Pc >= p is convex and star-shaped about the origin and along each ray from the
//     origin Pc decreases; its boundary radius rho(theta) is found by bisection, raised to
//     min_miss_m (the miss disk). Every local minimum of the cost over cam.boundary_angles
//     directions is refined by golden section; the best is the optimum of the fixed-plane
//     model. Near a whole number of orbits after the burn, radial and normal burns barely
//     move the miss point (A A^T nearly singular) and the cost has sharp valleys; the
//     along-track burn (below) is therefore a second start.
//  2. NLopt SLSQP (Kraft 1988) polishes the better start on the full linear model (the encounter plane
//     follows the relative velocity, the TCA moves): objective |dv|^2, constraints
//     ln(Pc/p) <= 0 and (min_miss - miss)/max(min_miss, 1 m) <= 0 with central-difference
//     gradients; it is kept only when it is feasible and not larger.
//     along_track_only: the same 1-D problem on dv_T, solved by bracketing and bisection of
//     the first feasible |dv_T| on each side.
//  3. Re-linearisation (Newton on the burn): the model is rebuilt about the burn found, from
//     its exact propagation, until the burn changes by less than cam.dv_tol_mps or after
//     cam.max_relinearizations models.
// Verification: the final burn's exact outcome (CamEncounter::outcome: two-body + J2
// propagation of the burned primary and the secondary to the refined new TCA, covariances
// propagated there, Pc recomputed).
// Recommended Pc. The model above is the 2D Pc; whether a burn is needed and whether the
// verified burn meets pc_max are decided by the recommended Pc (pc_method_choice.hpp: 2D
// when its usage checks pass, else 3D-Nc, else Monte Carlo) before the burn and at the new
// TCA (CamEncounter::recommended_pc). When the verified recommended Pc p_rec exceeds pc_max,
// the 2D target is corrected by the ratio the verification measured,
// target' = min(target, Pc_2D,verified) x pc_max (1 - cam.pc_margin) / p_rec,
// and the burn planned again, at most cam.max_target_corrections times (the ratio of the two
// methods varies slowly with the burn, so the correction converges in a few steps when the
// methods agree on the direction of the gradient; when it does not, verified_ok says so).
#pragma once

#include <string>
#include <vector>

#include "evade/cam/cam_encounter.hpp"
#include "evade/cam/cam_params.hpp"

namespace evade::cam {

struct CamRequest {
  double lead_s = 0.0;        ///< burn time before TCA [s]
  double pc_max = 1e-4;       ///< Pc threshold, in (0, 1)
  double min_miss_m = 0.0;    ///< smallest miss distance at the new TCA [m]
  bool along_track_only = false;
};

struct CamPlan {
  bool maneuver_needed = true;     ///< false: recommended Pc and miss already meet it, dv = 0
  double lead_s = 0.0;
  double burn_from_epoch_s = 0.0;  ///< burn time minus the epoch of the given states [s]
  double tca_from_epoch_s = 0.0;   ///< unburned TCA minus the epoch of the given states [s]
  StateEci primary_at_burn;        ///< before the burn
  Vec3 dv_rtn_mps = Vec3::Zero();  ///< R radial, T along track, N orbit normal [m/s]
  Vec3 dv_eci_mps = Vec3::Zero();
  double dv_mps = 0.0;
  double pc_target = 0.0;          ///< pc_max (1 - cam.pc_margin): what the planner aims at
  EncounterOutcome before;         ///< no burn
  EncounterOutcome predicted;      ///< the last linear model at the final burn
  EncounterOutcome predicted_first;  ///< the model about the unburned trajectory, same burn
  EncounterOutcome verified;       ///< exact propagation of the final burn (2D Pc)
  RecommendedPc before_recommended;    ///< no burn: the recommended Pc
  RecommendedPc verified_recommended;  ///< the final burn: the recommended Pc at its TCA
  bool verified_ok = false;        ///< verified recommended Pc <= pc_max and miss >= min_miss_m
  int target_corrections = 0;      ///< re-plans with a corrected 2D target
  double pc_target_2d = 0.0;       ///< the 2D target of the last plan
  int relinearizations = 0;        ///< linear models built
  double last_change_mps = 0.0;    ///< |burn change| at the last re-linearisation
  std::string search;              ///< how the burn was found
  int nlopt_result = 0;            ///< SLSQP's code in the last model (0: not run)
};

/// Checks the request (lead_s in (0, cam.max_lead_s], pc_max in (0, 1), min_miss_m >= 0,
/// finite) and throws std::invalid_argument naming the bad one.
void validate_cam_request(const CamRequest& req, const CamConfig& cfg);

/// The plan. Throws std::invalid_argument for a bad request or input (as assess does), and
/// when the threshold cannot be reached with |dv| <= cam.max_dv_mps (the burn needed named).
CamPlan plan_cam(const assessment::ConjunctionInput& in, const CamRequest& req, const assessment::AssessConfig& acfg,
                 const CamConfig& cfg);
/// The same on an encounter already set up for req.lead_s.
CamPlan plan_cam(const CamEncounter& enc, const CamRequest& req, const CamConfig& cfg);

/// One lead time of the trade space: the plan, or why there is none (e.g. unreachable).
struct CamSweepRow {
  double lead_s = 0.0;
  bool ok = false;
  std::string error;  ///< when !ok
  CamPlan plan;       ///< when ok
};
/// plan_cam at each lead (same request otherwise); a lead without a plan gives its error
/// in its row, the others go on.
std::vector<CamSweepRow> sweep_cam_lead(const assessment::ConjunctionInput& in, const std::vector<double>& leads_s,
                                        const CamRequest& req, const assessment::AssessConfig& acfg,
                                        const CamConfig& cfg);

/// The smallest burn of one linear model (steps 1 and 2 above) for Pc <= pc_target.
/// Throws std::invalid_argument when it needs more than cam.max_dv_mps.
Vec3 solve_cam_model(const CamLinearModel& m, const CamRequest& req, double pc_target,
                     const CamConfig& cfg, std::string* search, int* nlopt_result);

}  // namespace evade::cam
