// A conjunction seen from a burn of the primary (object1) made lead_s before the TCA: the
// exact outcome of a burn by propagation, and its linearisation about a reference burn.
//
// Outcome of a burn (CamEncounter::outcome): the primary's state at the burn time
// t_b = TCA - lead (two-body + J2 propagation back from the TCA of the assessment), the
// impulsive Δv added in the primary's own RTN frame at t_b, the burned primary and the
// secondary propagated (two-body + J2, DOP853 tight) to the new local TCA, refined by Newton
// on the range rate (dt = -(r.v)/|v|^2, |dt| < 1 us, as in assess.hpp), both covariances
// propagated to that TCA by Phi P Phi^T (Vallado 4th ed. sec. 10.7; the primary's from t_b
// along the burned trajectory, the secondary's from the first TCA), and the 2D Pc there
// (pc_2d.hpp). The burn is taken as exact (no execution error added to the covariance).
// 3x3 position covariances have no velocity block and are held constant, as in assess.hpp.
//
// Linear model about a reference burn dv_ref (CamLinearModel, built from the same
// propagation): the primary's state at the reference TCA moves by Phi_(r,v) C^T (dv - dv_ref)
// and Phi_(v,v) C^T (dv - dv_ref), with Phi the J2 state transition matrix from t_b
// (central differences, covariance_propagation.hpp) and C^T the RTN -> ECI rotation at t_b;
// the TCA moves by the rectilinear shift dt = -(r.v)/|v|^2; the covariances are those at the
// reference TCA. This is the first-order (Clohessy-Wiltshire-like) model of the burn; for an
// along-track burn it gives the classical along-track drift 3 dv_T t - (4 dv_T / n) sin(n t)
// (Vallado 4th ed. sec. 6.8, CW solution).
//
// Recommended Pc of a burn (CamEncounter::recommended_pc): the same exact propagation to the
// new TCA, both objects' full covariances (6x6 when given) propagated there, and the
// escalation of pc_method_choice.hpp (2D -> 3D-Nc -> Monte Carlo) run on those states as given
// (they are at the refined TCA), with the assessment's window (assessment.window_s) about it.
#pragma once

#include <string>

#include "evade/assessment/assess.hpp"

namespace evade::cam {

/// A conjunction after (or without) a burn, at its TCA.
struct EncounterOutcome {
  double tca_s = 0.0;         ///< TCA minus the TCA without a burn [s]
  double pc = 0.0;            ///< 2D Pc at that TCA
  double miss_m = 0.0;        ///< |r2 - r1| at that TCA [m]
  double rel_speed_mps = 0.0; ///< |v2 - v1| [m/s]
};

/// The Pc pc_method_choice.hpp recommends for an encounter, and why.
struct RecommendedPc {
  double pc = 0.0;
  std::string method = "2d";  ///< "2d", "3d_nc" or "mc"
  std::string why;            ///< one line
};

/// The linear model of a burn's effect about a reference burn (see above).
struct CamLinearModel {
  Vec3 dv_ref_rtn_mps = Vec3::Zero();
  double t_ref_s = 0.0;             ///< reference TCA minus the unburned TCA [s]
  StateEci primary_ref, secondary_ref;  ///< at the reference TCA
  Mat3 cov1_m2 = Mat3::Zero(), cov2_m2 = Mat3::Zero();  ///< position covariances there
  Mat3 dr_ddv = Mat3::Zero();       ///< d r1(TCA) / d dv_rtn
  Mat3 dv_ddv = Mat3::Zero();       ///< d v1(TCA) / d dv_rtn
  double hbr_m = 0.0;
  double pc_rel_tol = 1e-8;

  /// The model's outcome of burn dv_rtn_mps.
  EncounterOutcome predict(const Vec3& dv_rtn_mps) const;
};

class CamEncounter {
 public:
  /// Assesses `in` (brought to its TCA by assess) and places the burn lead_s before that TCA.
  /// Throws std::invalid_argument as assess does, or for lead_s not finite or <= 0.
  CamEncounter(const assessment::ConjunctionInput& in, double lead_s, const assessment::AssessConfig& cfg);

  const assessment::Assessment& assessment() const { return a_; }
  double lead_s() const { return lead_s_; }
  /// The primary at the burn time, before the burn.
  const StateEci& primary_at_burn() const { return burn_state_; }
  /// RTN (rows R, T, N of the primary at the burn) -> ECI.
  Mat3 rtn_to_eci() const { return rtn_to_eci_; }

  /// Exact outcome of a burn by propagation (see above). Throws std::invalid_argument when
  /// the new TCA is not found within assessment.tca_search_s of the first.
  EncounterOutcome outcome(const Vec3& dv_rtn_mps) const;
  /// The same propagation, returned as the linear model about dv_rtn_mps (its outcome too).
  CamLinearModel linearize(const Vec3& dv_rtn_mps, EncounterOutcome* at_ref = nullptr) const;
  /// The recommended Pc without a burn (the escalation on assessment()).
  RecommendedPc recommended_pc_before() const;
  /// The recommended Pc after burn dv_rtn_mps (see above); throws as outcome() does.
  RecommendedPc recommended_pc(const Vec3& dv_rtn_mps) const;

 private:
  struct Burned;
  Burned propagate_burn(const Vec3& dv_rtn_mps) const;

  assessment::Assessment a_;
  assessment::AssessConfig cfg_;
  EarthModel earth_;
  double lead_s_ = 0.0;
  double hbr_m_ = 0.0;
  bool six_[2] = {false, false};
  StateEci burn_state_;
  Mat6 cov1_burn_ = Mat6::Zero();
  Mat3 rtn_to_eci_ = Mat3::Identity();
};

}  // namespace evade::cam
