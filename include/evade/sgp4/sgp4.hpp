// SGP4/SDP4 analytic propagation of two-line mean elements in the TEME frame, after Vallado,
// Crawford, Hujsak & Kelso (2006), "Revisiting Spacetrack Report #3", AIAA 2006-6753:
// sgp4init (un-Kozai the mean motion, drag coefficients C1..C5 and D2..D4, secular rates
// from J2, J4, Hoots & Roehrich 1980 eq. for the near-Earth model) and sgp4 (secular drag
// and gravity, long-period J3 terms, Kepler's equation for the Lyddane variables, J2
// short-period terms), with the deep-space branch (period >= 225 min) in deep_space.hpp.
// Both operation modes: 'a' (AFSPC: the 1970-based sidereal time and the node quadrant
// handling of the operational code) and 'i' (improved: IAU-82 GMST, no quadrant fix).
// Errors are returned as the paper's codes, never thrown during propagation.
#pragma once

#include <Eigen/Core>

#include "evade/sgp4/deep_space.hpp"
#include "evade/sgp4/gravity_constants.hpp"
#include "evade/sgp4/mean_elements.hpp"

namespace evade::sgp4 {

enum class OperationMode : char { kAfspc = 'a', kImproved = 'i' };

/// The paper's error codes (5, "epoch elements are sub-orbital", is no longer raised).
enum class Sgp4Error : int {
  kNone = 0,
  kMeanEccentricity = 1,       ///< mean e >= 1 or e < -0.001
  kMeanMotion = 2,             ///< mean motion <= 0
  kPerturbedEccentricity = 3,  ///< perturbed e < 0 or e > 1 (deep space)
  kSemiLatusRectum = 4,        ///< semi-latus rectum < 0
  kSubOrbital = 5,
  kDecayed = 6,                ///< radius below one Earth radius
};

/// "mean eccentricity out of range (error 1)", ...
const char* sgp4_error_text(Sgp4Error e) noexcept;

/// A TEME state; r and v are meaningful for kNone and kDecayed (the reference returns the
/// state it computed before flagging decay), NaN otherwise.
struct Sgp4State {
  Sgp4Error error = Sgp4Error::kNone;
  Eigen::Vector3d r_teme_m = Eigen::Vector3d::Zero();
  Eigen::Vector3d v_teme_mps = Eigen::Vector3d::Zero();
};

/// Mean elements in the theory's units (radians, rad/min, 1/Earth radii).
struct Sgp4Elements {
  double epoch_days_1950 = 0.0;  ///< days since 1949 Dec 31 00:00 UTC (JD 2433281.5)
  double bstar_per_er = 0.0;
  double ecco = 0.0, inclo_rad = 0.0, nodeo_rad = 0.0, argpo_rad = 0.0, mo_rad = 0.0;
  double no_kozai_radpmin = 0.0;
};

/// Bounds of the distance from the Earth's centre over an interval of time.
struct RadiusBounds {
  bool bounded = false;   ///< false: no bound (deep space, or drag ending the orbit)
  double min_m = 0.0;     ///< |r| >= min_m at every instant of the interval [m]
  double max_m = 0.0;     ///< |r| <= max_m [m]
};

/// Bounds of the SGP4 path over an interval of time (near-Earth; path_bounds.cpp gives the
/// argument): the position is |r| (cos su N + sin su M), N = (cos node, sin node, 0),
/// M = (-sin node cos incl, cos node cos incl, sin incl), with node and incl in the ranges
/// below at every instant; |r| as a function of su is bounded by path_radius_in_arc.
struct PathBounds {
  bool bounded = false;           ///< false: no bound (deep space, or drag ending the orbit)
  double node_lo_rad = 0.0;       ///< node of the position (short-period terms included),
  double node_hi_rad = 0.0;       ///< unwrapped [rad]
  double incl_lo_rad = 0.0;       ///< inclination of the position [rad]
  double incl_hi_rad = 0.0;
  double du_rad = 0.0;            ///< |su - u| (u: the Lyddane argument of latitude) [rad]
  double am_lo = 0.0, am_hi = 0.0;        ///< mean semi-major axis [Earth radii]
  double em_lo = 0.0, em_hi = 0.0;        ///< mean eccentricity (after drag, clamped)
  double argp_lo_rad = 0.0, argp_hi_rad = 0.0;  ///< argument of perigee, unwrapped [rad]
  double y_lo = 0.0, y_hi = 0.0;  ///< aycof / (am (1 - em^2)) (long-period, J3)
  double con41 = 0.0, x1mth2 = 0.0;  ///< 3 cos^2 i - 1, 1 - cos^2 i (epoch inclination)
  double j2 = 0.0, re_m = 0.0;    ///< the theory's J2 and Earth radius [m]
  RadiusBounds radius;            ///< radius_bounds of the same interval
};

/// Bounds of |r| at every instant of the interval of b at which the position's argument of
/// latitude su lies in [s_lo_rad, s_hi_rad] (s_lo <= s_hi; any real values).
RadiusBounds path_radius_in_arc(const PathBounds& b, double s_lo_rad, double s_hi_rad) noexcept;

/// Converts catalog mean elements (degrees, rev/day) to the theory's units.
Sgp4Elements sgp4_elements(const MeanElements& m) noexcept;

class Sgp4Propagator;

/// True when propagate_near_x4 computes four lanes at once on this processor (x86-64 with
/// AVX2 and FMA, with glibc's vector sine and cosine); false elsewhere, where it computes one lane
/// after the other with propagate_min.
bool sgp4_x4_vectorized() noexcept;

/// TEME positions [m] and velocities [m/s] of four near-Earth propagators p[k] (deep_space()
/// false, init_error() kNone) at tsince_min[k], lane by lane the formulas of propagate_min
/// evaluated four at a time (sgp4_x4.cpp). They differ from propagate_min's only by the
/// roundings of the vector sine and cosine (at most 4 ulp where the scalar ones are within
/// 1): docs/VALIDATION.md bounds that by kSgp4X4PositionError_m, which sgp4_x4_test.cpp
/// checks on the shipped catalog. ok[k] is false where propagate_min
/// would report an error or a decay (or a correction leaves the small-angle range); that
/// lane's outputs are then unspecified and the caller uses propagate_min. Thread-safe.
void propagate_near_x4(const Sgp4Propagator* const p[4], const double tsince_min[4],
                       double r_teme_m[4][3], double v_teme_mps[4][3], bool ok[4]) noexcept;

/// The same for four deep-space propagators p[k] (deep_space() true, init_error() kNone):
/// the secular and resonance terms lane by lane as propagate_min computes them
/// (deep_space.cpp), then the lunar-solar periodics four at a time (deep_space_periodics'
/// formulas), the perturbed inclination's sine and cosine, the long- and short-period terms, Kepler's equation and the orientation four at a time (the formulas of
/// propagate_near_x4, with the perturbed inclination's coefficients as propagate_min takes
/// them). Within kSgp4X4DeepPositionErrorRel |r| of propagate_min's (sgp4_x4_test.cpp checks
/// it on the shipped catalog's deep-space element sets); ok[k] as for propagate_near_x4.
/// Thread-safe.
void propagate_deep_x4(const Sgp4Propagator* const p[4], const double tsince_min[4],
                       double r_teme_m[4][3], double v_teme_mps[4][3], bool ok[4]) noexcept;

/// Bytes of an Sgp4X4Lanes' gathered constants.
constexpr std::size_t kSgp4X4LanesBytes = 2048;

/// The constants of four propagators (all near-Earth or all deep-space, init_error() kNone),
/// gathered once for propagate_x4 at many instants (propagate_near_x4 and propagate_deep_x4
/// gather them at every call). Holds no pointer to them.
class Sgp4X4Lanes {
 public:
  Sgp4X4Lanes() = default;
  explicit Sgp4X4Lanes(const Sgp4Propagator* const p[4]) noexcept;
  bool deep() const noexcept { return deep_; }

 private:
  friend void propagate_x4(const Sgp4X4Lanes& lanes, const Sgp4Propagator* const p[4],
                           const double tsince_min[4], double r_teme_m[4][3],
                           double v_teme_mps[4][3], bool ok[4]) noexcept;
  bool deep_ = false;
  alignas(32) unsigned char storage_[kSgp4X4LanesBytes] = {};
};

/// propagate_near_x4 or propagate_deep_x4 (as lanes.deep()) of the propagators p, whose
/// constants lanes holds (Sgp4X4Lanes(p)).
void propagate_x4(const Sgp4X4Lanes& lanes, const Sgp4Propagator* const p[4],
                  const double tsince_min[4], double r_teme_m[4][3], double v_teme_mps[4][3],
                  bool ok[4]) noexcept;

/// Bound on |r_x4 - r| / |r| between propagate_near_x4 (or propagate_deep_x4) and propagate_min positions
/// (docs/VALIDATION.md: about 100 times the largest measured, 1.03e-15 on the shipped
/// catalog; a fortieth of the 4e-12 |r| jumps SGP4's own positions are allowed).
constexpr double kSgp4X4PositionErrorRel = 1e-13;
/// The same bound for propagate_deep_x4 (about 70 times the largest measured, 1.47e-14 on
/// the shipped catalog's deep-space element sets, from their eccentric orbits; a quarter of
/// the 4e-12 |r| jumps).
constexpr double kSgp4X4DeepPositionErrorRel = 1e-12;
/// The same as a distance [m]: 1 mm, far above kSgp4X4PositionErrorRel |r| for every
/// near-Earth orbit (period < 225 min, so |r| < 2 a < 2.4e7 m: 2.4e-6 m); a deep-space orbit
/// takes the larger of this and 10 kSgp4X4DeepPositionErrorRel r_max (conjunction::Sgp4Motion).
constexpr double kSgp4X4PositionError_m = 1e-3;

class Sgp4Propagator {
 public:
  /// sgp4init. Never throws; a bad element set shows up in init_error() (the state at
  /// epoch is evaluated once, as the reference does).
  Sgp4Propagator(const Sgp4Elements& el, OperationMode mode,
                 GravityModel gravity = GravityModel::kWgs72);
  Sgp4Propagator(const MeanElements& m, OperationMode mode = OperationMode::kImproved,
                 GravityModel gravity = GravityModel::kWgs72);

  /// The error code at epoch (kNone when the element set initialised cleanly).
  Sgp4Error init_error() const noexcept { return init_error_; }
  /// True for the deep-space branch (SDP4: period >= 225 min at initialisation).
  bool deep_space() const noexcept { return deep_; }
  /// State at tsince minutes from the element epoch. Thread-safe (const, no stored state).
  Sgp4State propagate_min(double tsince_min) const noexcept;
  /// State at t_s seconds from the element epoch.
  Sgp4State propagate_s(double t_s) const noexcept { return propagate_min(t_s / 60.0); }
  /// Bounds of |r| that propagate_min returns for every tsince in [t0_min, t1_min], from the
  /// theory's own formulas (radius_bounds.cpp gives the argument); near-Earth only: a
  /// deep-space element set, an init error or drag taking tempa to 0 gives bounded = false.
  RadiusBounds radius_bounds(double t0_min, double t1_min) const noexcept;
  /// Bounds of the path for every tsince in [t0_min, t1_min] (path_bounds.cpp); near-Earth
  /// only, bounded = false where radius_bounds has no bound.
  PathBounds path_bounds(double t0_min, double t1_min) const noexcept;

 private:
  friend class Sgp4X4Lanes;
  friend void propagate_x4(const Sgp4X4Lanes& lanes, const Sgp4Propagator* const p[4],
                           const double tsince_min[4], double r_teme_m[4][3],
                           double v_teme_mps[4][3], bool ok[4]) noexcept;
  struct Short {
    double con41, x1mth2, x7thm1, aycof, xlcof;
  };
  // The ranges of the mean semi-major axis am [Earth radii] and of the mean eccentricity
  // before the theory's clamp (e0 - B* C4 t - B* C5 (sin M - sin M0)) over [t0, t1] minutes
  // (radius_bounds.cpp, steps 1 and 2); ok = false when drag ends the orbit there.
  struct MeanRanges {
    bool ok = false;
    double am_lo = 0.0, am_hi = 0.0, em_lo = 0.0, em_hi = 0.0;
  };
  MeanRanges mean_ranges(double t0_min, double t1_min) const noexcept;
  void init_near_earth(double ao, double posq, double rteosq, double omeosq, double cosio,
                       double sinio, double rp);
  void init_drag_higher_order(double ao, double tsi, double sfour);
  Short short_period(double sinip, double cosip) const noexcept;
  // propagate_min up to the perturbed elements (secular gravity and drag, deep space's
  // secular, resonance and lunar-solar terms), the mean semi-major axis am [Earth radii] and
  // mean motion nm [rad/min]; an error code where propagate_min reports one there.
  Sgp4Error perturbed_min(double t, PerturbedElements& p, double& am, double& nm) const noexcept;
  // perturbed_min without the lunar-solar periodics (the elements dpper starts from).
  Sgp4Error mean_min(double t, PerturbedElements& p, double& am, double& nm) const noexcept;
  Sgp4State position_velocity(const PerturbedElements& p, double am, double nm) const noexcept;

  GravityConstants k_;
  OperationMode mode_;
  Sgp4Elements el_;
  DeepSpaceEpoch ep_;  // epoch values and near-Earth secular rates
  DeepSpaceTerms ds_;
  bool deep_ = false;
  bool isimp_ = false;
  double no_unkozai_ = 0.0;
  double cc1_ = 0, cc4_ = 0, cc5_ = 0, d2_ = 0, d3_ = 0, d4_ = 0, delmo_ = 0, eta_ = 0;
  double omgcof_ = 0, sinmao_ = 0, t2cof_ = 0, t3cof_ = 0, t4cof_ = 0, t5cof_ = 0;
  double xmcof_ = 0, nodecf_ = 0;
  Short near_{};  // short-period coefficients at epoch inclination
  // Near-Earth constants of every call, computed once exactly as propagate_min would
  // (the inclination and the Kozai-free mean motion do not change without deep space).
  double sin_inclo_ = 0.0, cos_inclo_ = 1.0;
  double am_near_ = 0.0;  // (xke / no_unkozai)^(2/3)
  Sgp4Error init_error_ = Sgp4Error::kNone;
};

/// Greenwich mean sidereal time (IAU-82, rad) at a UT1 Julian date, as the reference's gstime.
double gmst_iau82_rad(double jd_ut1) noexcept;

}  // namespace evade::sgp4
