// The 2D assessment of one encounter at TCA in flight form (docs/AUTONOMY.md AUT-4): the steps
// evade assess takes after it has the states at TCA, as one implementation that the node calls
// and that assess() and the usage checks call piece by piece:
//   1. the covariances checked and repaired by eigenvalue clipping (covariance.hpp's method:
//      Higham 1988; a symmetric matrix with an eigenvalue <= 0 is lifted to a floor);
//   2. the encounter plane and its principal axes (encounter_plane.hpp);
//   3. the 2D Pc on a workspace (pc_2d.hpp);
//   4. Chan's and Alfano's short-term encounter check (Chan 2008 ch. 4; Alfano 2005): the
//      encounter time 2 (5 sigma_along + HBR) / v_rel within a fraction of the shorter orbital
//      period, and the relative-speed sigma along the relative velocity within a fraction of v_rel;
//   5. CARA's 2D usage checks (Hall, Baars & Casali, "A multistep probability of collision
//      computational algorithm", AAS 23-398, 2023): with A the combined position covariance
//      (eigenvalues clipped at (1e-4 HBR)^2, CARA's Fclip), T = -r'A^-1 v / v'A^-1 v, its width
//      s = (v'A^-1 v)^-1/2, Ta,b = T -+ s sqrt(2) erfcinv(gamma): extended = min(1, (Tb - Ta)/P),
//      offset = min(1, max(|Ta|, |Tb|)/P), npd = a position covariance had an eigenvalue <= 0.
// No allocation, no exceptions: every problem is a status.
#pragma once

#include <array>
#include <cstdint>

#include "evade/assessment/assess_params.hpp"
#include "evade/assessment/encounter_plane.hpp"
#include "evade/assessment/pc_2d.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/state.hpp"

namespace evade::assessment {

enum class CovarianceStatus : std::uint8_t {
  kOk = 0,
  kNotFinite,           ///< a NaN or Inf entry
  kAsymmetric,          ///< |C - C^T| > 1e-9 |C|
  kNoPositiveEigenvalue,
  kNotConverged,        ///< the 6x6's Jacobi sweeps did not converge (symmetric_eigen.hpp)
};

/// Step 1 for a 3x3 and a 6x6 covariance: *out the matrix used (repaired when *npd), *min_eig
/// the smallest eigenvalue of the input.
CovarianceStatus repair_covariance_into(const Mat3& c, Mat3* out, bool* npd,
                                        double* min_eig) noexcept;
CovarianceStatus repair_covariance_into(const Mat6& c, Mat6* out, bool* npd,
                                        double* min_eig) noexcept;

/// Step 2: false when the relative speed is zero (no encounter plane: *out holds the miss).
bool encounter_plane_into(const StateEci& obj1, const Mat3& cov1_eci_m2, const StateEci& obj2,
                          const Mat3& cov2_eci_m2, EncounterPlane* out) noexcept;
/// False when the combined covariance in the plane is not positive definite.
bool principal_axes_into(const EncounterPlane& ep, PrincipalEncounter* out) noexcept;

/// The shorter of the two orbital periods (infinity for an unbound orbit) [s].
double shorter_period_s(const StateEci& s1, const StateEci& s2, const EarthModel& earth) noexcept;

/// Step 4's figures.
struct ShortTermValues {
  bool valid = true;
  double encounter_time_s = 0.0;
  double period_s = 0.0;
  double rel_speed_sigma_mps = 0.0;
  bool time_fails = false;   ///< the encounter lasts longer than the period fraction allows
  bool speed_fails = false;  ///< (only when the time holds) the speed sigma is too large
};
ShortTermValues short_term_values(const EncounterPlane& ep, const Mat6& c1, const Mat6& c2,
                                  const StateEci& s1, const StateEci& s2, double hbr_m,
                                  double max_period_fraction, double max_vel_sigma_ratio,
                                  const EarthModel& earth) noexcept;

/// Step 5's figures.
struct Usage2dValues {
  bool zero_speed = false;  ///< no relative velocity: extended and offset are 1
  double extended = 0.0;
  double offset = 0.0;
  bool npd = false;
};
/// conj_bound_factor: sqrt(2) erfcinv(gamma) (computed once at initialization);
/// min_pos_eig1/2: the smallest eigenvalues of the position covariances as given.
Usage2dValues usage_2d_values(const StateEci& s1, const Mat3& c1_pos, const StateEci& s2,
                              const Mat3& c2_pos, double min_pos_eig1, double min_pos_eig2,
                              double hbr_m, double conj_bound_factor,
                              const EarthModel& earth) noexcept;

/// What the whole 2D assessment needs besides the encounter (AssessConfig's fields).
struct Encounter2dConfig {
  double pc_rel_tol = 1e-8;
  double short_term_max_period_fraction = 0.01;
  double short_term_max_vel_sigma_ratio = 0.1;
  double conj_bound_factor = 0.0;  ///< sqrt(2) erfcinv(conj_duration_gamma)
  double pc2d_extended_cutoff = 0.02;
  double pc2d_offset_cutoff = 0.01;
};

enum class Encounter2dStatus : std::uint8_t {
  kOk = 0,
  kBadCovariance,   ///< a covariance is not finite, not symmetric or has no positive eigenvalue
  kZeroSpeed,       ///< no relative velocity: no encounter plane, no 2D Pc
  kNotPositive,     ///< the combined covariance in the plane is not positive definite
  kBadPc,           ///< pc_2d refused the encounter (Pc2dStatus)
};
const char* encounter_2d_status_name(Encounter2dStatus s) noexcept;

/// CARA's failed 2D checks as bits.
enum Usage2dBit : std::uint16_t {
  kUsageExtended = 1, kUsageOffset = 2, kUsageNpd = 4, kUsageShortTerm = 8
};

struct Encounter2d {
  std::array<Mat6, 2> cov_eci = {Mat6::Zero(), Mat6::Zero()};  ///< as used (repaired)
  std::array<bool, 2> npd = {false, false};
  EncounterPlane plane;
  PrincipalEncounter principal;
  Pc2dResult pc;
  ShortTermValues short_term;
  Usage2dValues usage;
  std::uint16_t failed = 0;  ///< Usage2dBit of the checks that fail
};

/// The 2D settings of an assessment configuration (the one declaration of each, assess_params):
/// what the node and evade assess both use. Computes erfcinv once: call it at initialization.
Encounter2dConfig encounter_2d_config(const AssessConfig& c) noexcept;

/// Steps 1 to 5 for two objects at TCA with 6x6 covariances.
Encounter2dStatus assess_encounter_2d(const StateEci& s1, const Mat6& c1, const StateEci& s2,
                                      const Mat6& c2, double hbr_m, const Encounter2dConfig& cfg,
                                      const EarthModel& earth, Pc2dWorkspace* ws,
                                      Encounter2d* out) noexcept;

}  // namespace evade::assessment
