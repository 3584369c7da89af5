// One spacecraft of one's own, on its own force model, screened against an SGP4 catalog by the
// robust screener (robust_screen.hpp; issue 43: the ground's review of a burn the node
// proposes). Object 0 is the own spacecraft: its J2000 state at the start propagated under
// two-body + J2 (the onboard response's model; DOP853, AdaptiveOptions::tight(), states kept
// every kNodeStep_s and carried from the nearest earlier one to any time), turned into TEME of
// date (the catalog's frame: sgp4::teme_to_j2000_matrix, interpolated linearly between the
// nodes, so the velocity returned is the exact time derivative of the position returned, the
// frames' rotation rate included). Objects 1..N are the catalog's (Sgp4Motion), in its order.
//
// The perturbation of object 0 against the screener's field (two-body + J2 of WGS-72 about the
// TEME pole) is p = M^T a(M r) + 2 M'^T v - a_ref(r), M the rotation TEME -> J2000: the J2
// about the J2000 pole and the other Earth model's constants, seen from TEME. It is known in
// closed form at any time and sampled at the times Sgp4Motion samples an orbit of the same
// period and eccentricity (envelope_sample_times), with the same factor and floor (accel =
// factor x largest |p| + floor, rate = 4 n_max accel): derived as the catalog's envelope is,
// and stated as its assumption in docs/AUTONOMY.md.
#pragma once

#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "evade/conjunction/sgp4_motion.hpp"

namespace evade::conjunction {

class OwnOrbitMotion final : public MotionSource {
 public:
  static constexpr double kNodeStep_s = 60.0;

  /// own_j2000: the spacecraft at start_j2000_s (UTC s since J2000) in J2000 [m, m/s], moved
  /// under two-body + J2 of earth over [0, span_s]; catalog: the SGP4 motion from the same
  /// start. Throws std::invalid_argument for a bad state or span, std::runtime_error when the
  /// propagation fails.
  OwnOrbitMotion(const StateEci& own_j2000, double start_j2000_s, double span_s,
                 const EarthModel& earth, std::shared_ptr<const Sgp4Motion> catalog,
                 const Sgp4MotionOptions& envelope = {});

  std::size_t size() const override { return 1 + catalog_->size(); }
  StateEci state_at(std::size_t i, double t_s) const override;
  PerturbationBound perturbation(std::size_t i) const override;
  double velocity_error_mps(std::size_t i) const override;
  StateEci grid_state_at(std::size_t i, double t_s) const override;
  void grid_states_at(double t_s, std::size_t begin, std::size_t end, StateEci* out) const override;
  bool acceleration_at(std::size_t i, double t_s, Vec3& a_mps2, double& error_mps2) const override;
  double grid_velocity_error_mps(std::size_t i) const override;
  double grid_position_error_m(std::size_t i) const override;
  bool has_grid_states() const override { return true; }
  EarthModel reference_earth() const override { return catalog_->reference_earth(); }
  std::string frame() const override { return "TEME"; }

  /// The own spacecraft in J2000 at t_s from the start [m, m/s].
  StateEci own_j2000_at(double t_s) const;
  /// The largest sampled |p| of the own spacecraft [m/s^2], for reports.
  double own_sampled_perturbation_mps2() const noexcept { return sampled_mps2_; }

 private:
  // M (TEME -> J2000) at t_s from the start and its time derivative (the interpolant's).
  void rotation_at(double t_s, Eigen::Matrix3d* m, Eigen::Matrix3d* m_dot) const;
  void sample_envelope(const Sgp4MotionOptions& envelope);

  std::shared_ptr<const Sgp4Motion> catalog_;
  EarthModel earth_;
  double span_s_ = 0.0;
  std::vector<StateEci> nodes_;          // J2000, every kNodeStep_s from the start
  std::vector<Eigen::Matrix3d> rot_;     // M at each node
  PerturbationBound bound_;
  double sampled_mps2_ = 0.0;
};

}  // namespace evade::conjunction
