// Conjunction assessment of one encounter: TCA refinement, covariance checks, the
// encounter plane, the Pc of every plane method of pc_methods.hpp (the 2D Pc by quadrature,
// Chan's series, Alfano's maximum Pc), the short-term validity test and, on request, the
// Monte Carlo Pc.
//
// States not at TCA (r.v != 0) are brought to the local TCA by two-body + J2 propagation of
// both objects (covariance_propagation.hpp): Newton iteration on the range rate,
// dt = -(r.v)/(|v|^2 + r.a_rel) (a_rel the two-body + J2 relative acceleration; |v|^2 alone
// where that sum is not positive) with r, v re-propagated each step, until |dt| < 1 us, within
// +- tca_search_s. 6x6 covariances are propagated to the new TCA with the J2 state
// transition matrix; 3x3 position covariances cannot be (no velocity block) and are held
// constant over the shift, which the result states.
// Short-term validity (Chan 2008 ch. 4; Alfano 2009): the 2D Pc assumes rectilinear relative
// motion during the encounter. The encounter time T = 2 (5 sigma_v + HBR) / v_rel, with
// sigma_v the combined position sigma along the relative velocity, is compared with the
// shorter orbital period (T <= f P), and the relative-speed uncertainty (6x6 covariances)
// with the relative speed (sigma <= g v_rel); either failure is reported with its reason,
// and the Monte Carlo Pc (monte_carlo_pc.hpp) is the estimate to use.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "evade/assessment/assess_params.hpp"
#include "evade/assessment/encounter_plane.hpp"
#include "evade/assessment/monte_carlo_pc.hpp"
#include "evade/assessment/pc_methods.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

struct ObjectState {
  std::string name;
  StateEci state;
  Mat6 cov_eci = Mat6::Zero();  ///< ECI [m^2, m^2/s, m^2/s^2]; velocity block zero if unknown
  bool has_velocity_cov = false;
};

struct ConjunctionInput {
  std::array<ObjectState, 2> obj;
  double hbr_m = 0.0;
  EarthModel earth = kEarthDefault;
};

struct ShortTermCheck {
  bool valid = true;
  double encounter_time_s = 0.0;
  double period_s = 0.0;
  double rel_speed_sigma_mps = 0.0;
  std::string reason;  ///< empty when valid
};

struct Assessment {
  std::array<ObjectState, 2> at_tca;  ///< states and covariances used (after TCA shift, repair)
  /// The covariances at TCA before any repair (3D-Nc takes a slightly NPD one as given, as
  /// NASA CARA's Pc3D_Hall does) [m^2, m^2/s, m^2/s^2].
  std::array<Mat6, 2> cov_unrepaired_eci = {Mat6::Zero(), Mat6::Zero()};
  double tca_shift_s = 0.0;       ///< TCA minus the epoch of the given states
  std::string tca_method;         ///< how the states were brought to TCA
  std::string covariance_propagation;
  std::array<bool, 2> npd = {false, false};  ///< covariance repaired by eigenvalue clipping
  std::array<double, 2> min_eigenvalue = {0.0, 0.0};
  /// Smallest eigenvalue of each 3x3 position covariance as given (before any repair) [m^2]:
  /// the 2D usage check's NPD indicator (pc_method_choice.hpp).
  std::array<double, 2> min_position_eigenvalue_m2 = {0.0, 0.0};
  EncounterPlane plane;
  PrincipalEncounter principal;
  /// Every plane method's Pc (pc_methods.hpp: 2D, Chan, max), in table order; NaN when the
  /// relative speed is zero (no encounter plane).
  std::vector<PcValue> plane_pc;
  ShortTermCheck short_term;
  std::optional<MonteCarloResult> mc;
};

/// Throws std::invalid_argument on bad input (hbr <= 0, zero relative speed, TCA not found
/// within tca_search_s).
/// With mc: its Monte Carlo too (window_s <= 0: mc_window_s), run by runner (empty: the
/// threaded runner; distributed_pc_monte_carlo.hpp spreads it over MPI ranks).
Assessment assess(const ConjunctionInput& given, const AssessConfig& cfg,
                  const std::optional<MonteCarloOptions>& mc = std::nullopt,
                  const McBlockRunner& runner = {});

/// The Monte Carlo window for an assessment: min((k sigma_max + HBR) / v_rel, P/2).
double mc_window_s(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                   const EarthModel& earth);

/// The shorter two-body period of the two objects at TCA [s] (+infinity when both are unbound).
double shorter_period_s(const Assessment& a, const EarthModel& earth);

/// Both objects at TCA (states and covariances used) as a Monte Carlo problem.
McEncounter mc_encounter(const Assessment& a, double hbr_m, const EarthModel& earth);

/// Pc only (2D quadrature) of two objects already at TCA, covariances used as given after
/// repair; the planner's inner evaluation.
double pc_at_tca(const ObjectState& o1, const ObjectState& o2, double hbr_m, double rel_tol);

}  // namespace evade::assessment
