// The simulation's truth: two bodies, a held thrust, the first closest approach
// (include/evade/sim/internal/thrusted_truth.hpp).
#include "evade/sim/internal/thrusted_truth.hpp"

#include <stdexcept>
#include <string>

#include "evade/dynamics/gravity.hpp"

namespace evade::sim {

Vec12 pack(const StateEci& sat, const StateEci& deb) {
  Vec12 x;
  x << sat.r_eci_m, sat.v_eci_mps, deb.r_eci_m, deb.v_eci_mps;
  return x;
}

ThrustedTruth::ThrustedTruth(const SimConfig& cfg, SimResult* out)
    : cfg_(cfg),
      out_(*out),
      integ_(Dop853<Vec12>::Rhs([this](double, const Vec12& x) { return derivative(x); }),
             cfg.integrator),
      x_(pack(cfg.satellite0, cfg.debris0)) {
  eo_.direction = EventDirection::kRising;
  eo_.time_tol_s = 1e-10;
}

Vec12 ThrustedTruth::derivative(const Vec12& x) const {
  Vec12 d;
  d.head<6>() = orbit_derivative(x.head<6>(), cfg_.gravity, cfg_.earth);
  d.segment<3>(3) += a_thrust_;
  d.tail<6>() = orbit_derivative(x.tail<6>(), cfg_.gravity, cfg_.earth);
  return d;
}

void ThrustedTruth::advance_unforced_to(double t_s) {
  if (t_s == 0.0) return;
  integ_.reset(0.0, x_);
  while (integ_.t_s() != t_s) {
    if (!integ_.step(t_s)) throw std::runtime_error("sim: " + integ_.failure_reason());
  }
  x_ = integ_.x();
}

bool ThrustedTruth::integrate(double t0_s, double t1_s, const std::function<void()>& on_step) {
  bool found_now = false;
  integ_.reset(t0_s, x_);
  double g_prev = closing_g(x_);
  while (integ_.t_s() != t1_s) {
    if (!integ_.step(t1_s)) throw std::runtime_error("sim: " + integ_.failure_reason());
    if (on_step) on_step();
    const double g_now = closing_g(integ_.x());
    if (!ca_found_) found_now = check_closest_approach(g_prev, g_now, t0_s) || found_now;
    g_prev = g_now;
  }
  if (!ca_found_) add_thrust_time(t1_s - t0_s);
  x_ = integ_.x();
  return found_now;
}

bool ThrustedTruth::check_closest_approach(double g_prev, double g_now, double t0_s) {
  auto g = [](double, const Vec12& xs) { return closing_g(xs); };
  auto ev = locate_event_in_step(integ_, g, g_prev, g_now, eo_);
  if (!ev) return false;
  ca_found_ = true;
  out_.closest_approach_found = true;
  out_.tca_s = ev->t_s;
  out_.miss_m = (ev->x.segment<3>(6) - ev->x.segment<3>(0)).norm();
  add_thrust_time(ev->t_s - t0_s);  // Δv and burn time of this segment up to the approach
  return true;
}

void ThrustedTruth::add_thrust_time(double dt_s) {
  const double an = a_thrust_.norm();
  if (an > 0.0) {
    out_.dv_mps += an * dt_s;
    out_.burn_s += dt_s;
  }
}

}  // namespace evade::sim
