// A catalog of SGP4 element sets as screening objects (issue 12): each object moves by
// SGP4/SDP4 (Vallado, Crawford, Hujsak & Kelso 2006, AIAA 2006-6753; evade/sgp4) in TEME,
// from a common start (by default the latest element epoch of the catalog).
//
// Frame: the states are TEME coordinates as SGP4 returns them. Distances between objects at
// one instant do not depend on the frame (TEME and J2000 differ by a rotation), so the
// conjunctions (pairs, TCA, miss, relative speed) are the same in either; the slow rotation
// of TEME of date against J2000 (precession and nutation, ~1e-11 rad/s) is part of the
// perturbation the bound below covers.
//
// Velocity: SGP4's own velocity is not the time derivative of its position (they differ by
// 1-10 cm/s in LEO, from the truncated short-period terms), so the velocity returned here is
// the central difference (r(t + tau) - r(t - tau)) / (2 tau), tau = velocity_step_s. Its
// error is tau^2 |r'''| / 6 (4e-6 m/s in LEO at tau = 0.05 s) plus the position's own
// non-smoothness over 2 tau: SGP4 stops Newton's iteration on Kepler's equation when the
// correction is below 1e-12 rad and keeps the sine and cosine of the previous iterate, so
// the position jumps by up to ~1e-12 a (7 um in LEO) where the iteration count changes,
// i.e. up to 7e-5 m/s in this velocity.
//
// Perturbation bound (MotionSource): p(t) = r''(t) - a(r(t)), a = two-body + J2 with SGP4's
// WGS-72 constants, is the SGP4 motion's departure from that field (J3, J4, drag, the
// truncation of SGP4's short-period terms, lunar-solar terms in deep space). It is sampled
// once per object over the span (three-point second difference of the SGP4 positions, step
// envelope_step_s = 2.5 s, each sample within E = 4 n_max^4 |r| h^2 / 12 + 16e-12 |r| / h^2:
// the truncation and the 7 um jumps above, 4.4e-5 m/s^2 in LEO) at samples_per_orbit
// samples per orbit, compressed by (1 - e)^1.5 for eccentric orbits; accel_mps2 =
// envelope_factor x (the largest sample + the largest E) + floor, and rate_mps3 = 4 n_max x
// accel_mps2 with n_max the largest angular rate of the orbit, n (1 + e)^2 / (1 - e^2)^1.5.
// This envelope is derived, not proven: docs/VALIDATION.md states it as the theorem's
// assumption and how it is checked.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "evade/conjunction/motion_source.hpp"
#include "evade/conjunction/types.hpp"
#include "evade/sgp4/mean_elements.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::conjunction {

/// Allowed |SGP4 velocity - d/dt SGP4 position| of an object: kVelocityAllowanceMps +
/// kVelocityAllowanceFraction x its speed bound (measured: 0.1 m/s in LEO, 2.6 m/s at the
/// perigee of 12-hour HEO orbits, where SDP4's velocity leaves out its resonance and
/// lunar-solar rates: 2.6e-4 of the speed). Used by the time filter
/// (primary_time_filter.hpp) and for the broad phase's grid states (grid_state_at below).
constexpr double kVelocityAllowanceMps = 1.0;
constexpr double kVelocityAllowanceFraction = 1e-3;
inline double velocity_allowance_mps(double speed_bound_mps) {
  return kVelocityAllowanceMps + kVelocityAllowanceFraction * speed_bound_mps;
}

struct Sgp4MotionOptions {
  double span_s = 86400.0;        ///< screened span from the start [s]
  bool start_at_latest_epoch = true;
  double start_j2000_s = 0.0;     ///< start (UTC s since J2000) when not the latest epoch
  sgp4::OperationMode mode = sgp4::OperationMode::kImproved;
  double velocity_step_s = 0.05;  ///< tau of the velocity's central difference [s]
  double accel_step_s = 5.0;      ///< step h of the acceleration's 5-point difference [s]
  /// Step h of the envelope samples' 3-point second difference [s], (0, 10]: its error,
  /// 4 n_max^4 |r| h^2 / 12 + 16e-12 |r| / h^2, is smallest near 2.3 s in LEO (4.4e-5 m/s^2
  /// at 2.5 s) and is added to the samples.
  double envelope_step_s = 2.5;
  int samples_per_orbit = 64;     ///< perturbation envelope samples (times (1 - e)^-1.5)
  long max_samples = 20000;       ///< cap per object (spread over the span)
  /// The envelope is sampled over one orbit (samples_per_orbit samples) every
  /// envelope_block_gap_s from the start, and over the span's last orbit, rather than over
  /// every orbit; 0 (or a gap not longer than the orbit): every orbit. The largest |p| of an
  /// orbit changes on the time scales of the orbit's slow motion (apsides and node: weeks;
  /// drag: grows with time, hence the last orbit; lunar-solar terms: days), checked in
  /// docs/VALIDATION.md against every orbit sampled [s].
  double envelope_block_gap_s = 21600.0;
  double envelope_factor = 2.0;   ///< accel_mps2 = factor x largest sample + floor
  double envelope_floor_mps2 = 5e-6;
  double object_size_m = 0.0;     ///< SpaceObject::size_m given to every object
  int threads = 1;                ///< threads of the setup (the envelopes), >= 1
  /// The envelopes split between processes (MPI ranks, issue 24): this process samples the
  /// element sets k with k mod parts == part, into a vector of kEnvelopeRecord doubles per
  /// element set, 0 where it samples nothing; sum_over_parts must then replace every entry
  /// by its sum over the processes, in every process (MPI_Allreduce with MPI_SUM). Each
  /// entry is non-zero in one process at most and x + 0 = x exactly, so every process ends
  /// with the envelopes one process alone computes, bit for bit. parts = 1: no sharing.
  int part = 0;
  int parts = 1;
  std::function<void(std::vector<double>&)> sum_over_parts;
  /// false: no perturbation envelope (states only, for reports and CDMs; perturbation() is
  /// +inf, so the robust screener proves nothing with it). SGP4 errors inside the span are
  /// then not looked for.
  bool envelopes = true;
  /// Throws std::invalid_argument naming the field.
  void validate() const;

 private:
  void validate_steps() const;
  void validate_envelope() const;
  void validate_parts() const;
};

/// Doubles per element set in Sgp4MotionOptions::sum_over_parts' vector: the largest
/// sampled |p| and its stencil error [m/s^2], the SGP4 error code that stopped the sampling
/// (0: none) and the time of that sample from the start [s].
constexpr std::size_t kEnvelopeRecord = 4;

/// An element set left out of the screening, and why.
struct RejectedElementSet {
  long norad_id = 0;
  std::string name;
  std::string reason;  ///< e.g. "SGP4 error 6 (decayed) at t = 5400 s"
  /// "NORAD 12345 (NAME): REASON".
  std::string message() const;
};

/// The SGP4 motion of the accepted element sets (MotionSource for the screeners).
class Sgp4Motion : public MotionSource {
 public:
  std::size_t size() const override { return props_.size(); }
  StateEci state_at(std::size_t i, double t_s) const override;
  PerturbationBound perturbation(std::size_t i) const override { return bounds_[i]; }
  /// Five-point second difference of the positions at step accel_step_s h: error below
  /// h^4 |r^(6)| / 90 (taken as 4 n_max^6 |r| h^4 / 90) plus the position jumps,
  /// (34 / 12) 4e-12 |r| / h^2 (3e-6 m/s^2 in LEO at h = 5 s).
  bool acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const override;
  /// tau^2 n_max^3 r_max / 3 + 4e-12 r_max / tau (truncation with a factor 2; the jumps).
  double velocity_error_mps(std::size_t i) const override { return v_err_mps_[i]; }
  /// One SGP4 evaluation with SGP4's own velocity (state_at takes three: the central
  /// difference). Throws as state_at.
  StateEci grid_state_at(std::size_t i, double t_s) const override;
  /// grid_state_at of each object, four near-Earth or four deep-space ones at a time where
  /// the processor has AVX2 (sgp4::propagate_near_x4, sgp4::propagate_deep_x4; a lane they
  /// flag is computed by grid_state_at).
  void grid_states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out) const override;
  /// velocity_allowance_mps of the escape speed at the Earth's radius, sqrt(2 mu / Re) =
  /// 11.2 km/s (no accepted object is faster: every perigee is above Re): 12.2 m/s; plus
  /// 1e-6 m/s for the four-lane states (sgp4_x4_test.cpp measures below 1e-9 m/s).
  double grid_velocity_error_mps(std::size_t i) const override;
  /// sgp4::kSgp4X4PositionError_m (1 mm) for a near-Earth object whose grid states are
  /// computed four at a time; for a deep-space one the larger of that and
  /// 10 kSgp4X4DeepPositionErrorRel r_max (r_max its largest radius as velocity_error_mps takes
  /// it: 1 mm for every orbit inside 1e8 m); else 0.
  double grid_position_error_m(std::size_t i) const override;
  bool has_grid_states() const override { return true; }
  EarthModel reference_earth() const override;
  std::string frame() const override { return "TEME"; }

  /// The largest sampled |p| of object i (before its stencil error, the factor and the
  /// floor), for reports.
  double sampled_perturbation_mps2(std::size_t i) const { return sampled_[i]; }

 private:
  friend struct Sgp4CatalogBuilder;
  bool four_lane(std::size_t i) const { return four_lane_[i] != 0; }
  bool deep_lane(std::size_t i) const { return four_lane_[i] == 2; }
  /// Objects per window of the prepared lane groups (the screening's step runner asks for
  /// grid states in chunks of as many: each is one window).
  static constexpr std::size_t kLaneWindow = 64;
  // Four near-Earth or four deep-space objects of one window (a short group repeats its last
  // object; n are its own).
  struct LaneGroup {
    std::array<std::uint32_t, 4> obj{};
    std::size_t n = 0;
  };
  // The groups of each window [w kLaneWindow, (w + 1) kLaneWindow) and their constants,
  // gathered once (sgp4::Sgp4X4Lanes); window w has groups [first[w], first[w + 1]).
  void build_lane_groups();
  // The grid states of window w's objects (its prepared groups, the rest one by one).
  void window_states(std::size_t w, double t_s, StateEci* out) const;
  // The grid states of objects [begin, end), grouped by four on the spot.
  void grouped_states(double t_s, std::size_t begin, std::size_t end, StateEci* out) const;
  // The grid states of the objects of [begin, end) not computed four at a time.
  void scalar_states(double t_s, std::size_t begin, std::size_t end, StateEci* out) const;
  // The grid states of group lg's own objects from its lanes (a flagged lane by grid_state_at).
  void group_states(const LaneGroup& lg, const sgp4::Sgp4X4Lanes& lanes, double t_s,
                    StateEci* out) const;
  // The groups of four near-Earth, then four deep-space objects of [begin, end), in object
  // order, and a group's constants.
  std::vector<LaneGroup> lane_groups(std::size_t begin, std::size_t end) const;
  sgp4::Sgp4X4Lanes lanes_of(const LaneGroup& lg) const;
  std::vector<LaneGroup> groups_;
  std::vector<sgp4::Sgp4X4Lanes> group_lanes_;
  std::vector<std::size_t> window_first_group_;
  std::vector<sgp4::Sgp4Propagator> props_;
  std::vector<double> offset_s_;  // start - element epoch [s]
  std::vector<char> four_lane_;   // grid states four at a time: 1 propagate_near_x4, 2 _deep_x4
  std::vector<double> grid_err_m_;  // grid_position_error_m of each object
  std::vector<long> norad_;
  std::vector<std::string> names_;
  std::vector<PerturbationBound> bounds_;
  std::vector<double> sampled_;
  std::vector<double> n_max_radps_;  // largest angular rate of each orbit
  std::vector<double> v_err_mps_;
  double velocity_step_s_ = 0.05;
  double accel_step_s_ = 5.0;
};

/// A catalog ready to screen: objects (state at the start, name "NORAD NAME"), their motion,
/// and what was rejected (SGP4 error at initialisation or at any envelope sample of the span,
/// perigee below the Earth's radius).
struct Sgp4Screening {
  std::vector<SpaceObject> objects;
  std::vector<long> norad_ids;
  std::vector<std::size_t> element_index;  ///< of each object in the element sets given
  std::shared_ptr<const Sgp4Motion> motion;
  std::vector<RejectedElementSet> rejected;
  double start_j2000_s = 0.0;
  long envelopes_sampled = 0;  ///< by this process (all of them unless split: parts > 1)
};

/// The times (from the start) at which the perturbation envelope of an orbit with this
/// period and eccentricity is sampled over [0, span] (Sgp4MotionOptions: samples_per_orbit,
/// max_samples, envelope_block_gap_s), ascending.
std::vector<double> envelope_sample_times(double period_s, double eccentricity,
                                          const Sgp4MotionOptions& opt);

/// Builds the screening of `elements` (the catalog's entries, in order).
Sgp4Screening sgp4_screening(const std::vector<sgp4::MeanElements>& elements,
                             const Sgp4MotionOptions& opt);

/// WGS-72 (the constants SGP4 element sets are fitted with) as an EarthModel.
EarthModel wgs72_earth();

}  // namespace evade::conjunction
