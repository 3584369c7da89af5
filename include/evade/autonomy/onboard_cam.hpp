// The onboard avoidance burn (docs/AUTONOMY.md AUT-5): the smallest impulse at a burn time
// inside the event's window after which the event's 2D Pc is at most its post-burn target, in
// flight form (no allocation, no exceptions, every loop bounded by the options' counts).
//
// The model is evade plan cam's (cam_planner.hpp, step 1 and 3) without its NLopt polish:
//  1. The encounter after a burn dv (ECI) at t_b: the primary propagated back from TCA to t_b
//     with its transition matrix (orbit_stm.hpp, two-body + J2, RK4 at step_s), dv added, the
//     burned primary and the secondary propagated to the new TCA (Newton on the range rate,
//     dt = -(r.v)/|v|^2, at most kTcaIterations), both covariances carried there by
//     Phi P Phi^T (Vallado 4th ed. sec. 10.7; the primary's along the burned trajectory), and
//     the 2D Pc in the encounter plane there (assessment::pc_2d on the caller's workspace).
//  2. Linearized about a burn, the miss point in the principal axes of the plane moves as
//     m = m_ref + A (dv - dv_ref), A = -Q^T [x; z] Phi_rv (the plane held fixed). The smallest
//     burn reaching a point m is dv = A^+ (m - m0), m0 = m_ref - A dv_ref, with |dv|^2 =
//     (m - m0)^T (A A^T)^-1 (m - m0). The region Pc >= p is convex and star-shaped about the
//     origin (a Gaussian convolved with the hard-body disk is log-concave: Prekopa 1973), so
//     along each direction theta the Pc falls through p once, at a radius found by regula
//     falsi (Illinois) on ln(Pc / p);
//     the cost is swept over boundary_angles directions and its best direction refined by
//     golden section (golden_iterations).
//  3. The model is rebuilt about the burn found (relinearizations) until the burn changes by
//     less than dv_tol_mps; the last model is the burn's exact outcome (step 1). Where that
//     outcome's Pc is above the aim, the aim is lowered by the ratio measured, as evade plan
//     cam does (at most target_corrections times).
// The aim is pc_target (1 - pc_margin), plan cam's. Over the window, burn_times candidate times
// spread evenly from the later of the window's start and now + min_lead_s to its end; the
// smallest verified burn wins. Every other tracked event is then checked with the chosen burn
// (check_other_event): a burn must not raise another event above its red threshold.
#pragma once

#include <cstdint>

#include "evade/assessment/encounter_plane.hpp"
#include "evade/assessment/pc_2d.hpp"
#include "evade/autonomy/conjunction_event.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/param.hpp"
#include "evade/core/state.hpp"

namespace evade::autonomy {

struct OnboardCamOptions {
  static constexpr int kMaxBurnTimes = 64;
  // Ranges and meanings: cam_options_params() (onboard_cam_params.cpp).
  int burn_times = 8;            ///< candidate burn times over the window
  int boundary_angles = 72;      ///< directions of the boundary sweep
  int bisections = 40;           ///< root steps of the boundary radius along a direction
  int golden_iterations = 25;    ///< refinement of each local minimum of the sweep
  int relinearizations = 6;      ///< models about the burned trajectory
  int target_corrections = 3;    ///< lowered aims after the exact outcome
  double step_s = 5.0;           ///< RK4 step of every propagation [s]
  double max_dv_mps = 1.0;       ///< largest burn [m/s]
  double pc_margin = 1e-3;       ///< the aim is pc_target (1 - margin) [-]
  double dv_tol_mps = 1e-6;      ///< convergence of the re-linearization [m/s]
  double min_lead_s = 60.0;      ///< no burn sooner than this after now [s]
  double pc_rel_tol = 1e-8;      ///< of the 2D Pc quadrature [-]
};

enum class CamStatus : std::uint8_t {
  kOk = 0,
  kNotNeeded,        ///< the event's Pc is already at most its target: no burn
  kBadOptions,       ///< a count or a value outside its range
  kNoBurnTime,       ///< no candidate time in the window (it closes before now + min_lead_s)
  kPropagation,      ///< a propagation failed (state out of the physical range)
  kNoEncounter,      ///< zero relative speed or a covariance that is not positive definite
  kUnreachable,      ///< no burn within max_dv_mps brings the Pc to the target
};
const char* cam_status_name(CamStatus s) noexcept;

/// The encounter after a burn, at its TCA, and the model about that burn (step 2).
struct BurnOutcome {
  double tca_shift_s = 0.0;      ///< the new TCA minus the event's [s]
  double pc = 0.0;               ///< 2D Pc there
  double miss_m = 0.0;           ///< |r2 - r1| there [m]
  assessment::PrincipalEncounter principal;  ///< miss and sigmas in the principal axes
  Eigen::Matrix<double, 2, 3> a = Eigen::Matrix<double, 2, 3>::Zero();  ///< d miss / d dv_eci
};

struct CamProposal {
  CamStatus status = CamStatus::kNoBurnTime;
  double burn_from_tca_s = 0.0;  ///< the burn time minus TCA [s] (< 0)
  Vec3 dv_eci_mps = Vec3::Zero();
  Vec3 dv_rsw_mps = Vec3::Zero();  ///< R radial, S along track, W orbit normal at the burn
  double pc_before = 0.0;        ///< the event's 2D Pc without a burn
  BurnOutcome after;             ///< the exact outcome of the burn (step 1)
  double aim = 0.0;              ///< the last aim of the boundary solve
  int relinearizations = 0;
  int target_corrections = 0;
};

/// Workspace: the 2D Pc's quadrature (16 KiB); preallocate one where nothing may allocate.
struct CamWorkspace {
  assessment::Pc2dWorkspace pc;
};

/// The options' parameter table (onboard_cam_params.cpp): each field's unit, range, meaning.
ParamTable<OnboardCamOptions> cam_options_params() noexcept;
/// The range check of the options, by that table.
bool cam_options_ok(const OnboardCamOptions& o) noexcept;

/// Step 1: the exact outcome of burn dv_eci at burn_from_tca_s (< 0) for event e.
CamStatus burn_outcome(const ConjunctionEvent& e, double burn_from_tca_s, const Vec3& dv_eci_mps,
                       const OnboardCamOptions& o, const EarthModel& earth, CamWorkspace* ws,
                       BurnOutcome* out) noexcept;

/// Steps 2 and 3 at one burn time.
CamStatus plan_burn_at(const ConjunctionEvent& e, double burn_from_tca_s, const OnboardCamOptions& o,
                       const EarthModel& earth, CamWorkspace* ws, CamProposal* out) noexcept;

/// The candidate burn times (see the file comment) as offsets from TCA [s, < 0] into taus_s
/// (room for OnboardCamOptions::kMaxBurnTimes); returns how many, 0 when the window has none
/// (or the options are out of range).
int candidate_burn_times(const ConjunctionEvent& e, std::int64_t now_us, const OnboardCamOptions& o,
                         double* taus_s) noexcept;

/// The smallest verified burn over the window's candidate times (see the file comment).
CamStatus plan_burn(const ConjunctionEvent& e, std::int64_t now_us, const OnboardCamOptions& o,
                    const EarthModel& earth, CamWorkspace* ws, CamProposal* out) noexcept;

/// Another tracked event after the proposal's burn (made at proposal_burn_us on the node's time
/// base): its exact outcome, and whether its Pc stays at or below its red threshold.
CamStatus check_other_event(const ConjunctionEvent& other, std::int64_t burn_us, const Vec3& dv_eci_mps,
                            const OnboardCamOptions& o, const EarthModel& earth, CamWorkspace* ws,
                            BurnOutcome* out, bool* within_red) noexcept;

}  // namespace evade::autonomy
