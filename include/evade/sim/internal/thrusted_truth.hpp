// Internal (not installed): the truth of the paper-000 simulation (Yao & Wang 2012, sec. 4)
// shared by the lockstep loop (simulator.cpp) and the real-time loop (realtime_simulator.cpp):
// satellite and debris under two-body (+ J2) gravity (Vallado eq. 8-30) integrated together by
// DOP853 (HNW I sec. II.10), the satellite's thrust held constant over each segment (the
// integrator restarts at every change, so no step straddles a discontinuity), the first
// closest approach located as the rising zero of g = (r_d − r_s)·(v_d − v_s) on the dense
// output (Brent), and the Δv and burn time of the thrust in force up to it.
#pragma once

#include <functional>

#include <Eigen/Core>

#include "evade/dynamics/dop853.hpp"
#include "evade/dynamics/events.hpp"
#include "evade/sim/sim_config.hpp"
#include "evade/sim/simulator.hpp"

namespace evade::sim {

using Vec12 = Eigen::Matrix<double, 12, 1>;

Vec12 pack(const StateEci& sat, const StateEci& deb);
inline StateEci sat_of(const Vec12& x) { return {x.segment<3>(0), x.segment<3>(3)}; }
inline StateEci deb_of(const Vec12& x) { return {x.segment<3>(6), x.segment<3>(9)}; }
/// g = rel_r · rel_v: negative while closing, rising through 0 at a closest approach.
inline double closing_g(const Vec12& x) {
  return (x.segment<3>(6) - x.segment<3>(0)).dot(x.segment<3>(9) - x.segment<3>(3));
}

class ThrustedTruth {
 public:
  /// Starts at the scenario's epoch states. The closest approach, Δv and burn time go to *out
  /// (closest_approach_found, tca_s, miss_m, dv_mps, burn_s), which must outlive this.
  ThrustedTruth(const SimConfig& cfg, SimResult* out);
  ThrustedTruth(const ThrustedTruth&) = delete;
  ThrustedTruth& operator=(const ThrustedTruth&) = delete;

  /// Unforced from t = 0 to t_s (the detection time).
  void advance_unforced_to(double t_s);
  /// Integrates [t0_s, t1_s] under the thrust in force, calling on_step after every accepted
  /// step (integrator() then holds it). Returns true when the closest approach was found in
  /// this segment (Δv and burn time are then counted only up to it).
  bool integrate(double t0_s, double t1_s, const std::function<void()>& on_step);

  void set_thrust(const Vec3& a_eci_mps2) { a_thrust_ = a_eci_mps2; }
  const Vec3& thrust() const { return a_thrust_; }
  const Vec12& x() const { return x_; }  ///< at the end of the last segment
  const Dop853<Vec12>& integrator() const { return integ_; }
  bool closest_approach_found() const { return ca_found_; }

 private:
  Vec12 derivative(const Vec12& x) const;
  bool check_closest_approach(double g_prev, double g_now, double t0_s);
  void add_thrust_time(double dt_s);

  const SimConfig& cfg_;
  SimResult& out_;
  Vec3 a_thrust_ = Vec3::Zero();
  Dop853<Vec12> integ_;
  Vec12 x_;
  EventOptions eo_;
  bool ca_found_ = false;
};

}  // namespace evade::sim
