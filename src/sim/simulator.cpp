// Closed-loop close-range evasion simulation (paper 000 sec. 4): truth with two-body + J2
// (Vallado eq. 8-30 via the dynamics module) integrated by DOP853 (HNW I sec. II.10) for both
// objects at once, thrust as a zero-order hold between command changes (the integrator is
// restarted at every change so no step straddles a discontinuity), closest approach located
// as the rising zero of g = (r_d − r_s)·(v_d − v_s) on the dense output (Brent).
#include "evade/sim/simulator.hpp"

#include "evade/sim/sim_params.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "evade/dynamics/events.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/sim/actuator_model.hpp"
#include "evade/sim/sensor_model.hpp"

namespace evade::sim {

namespace {

using Vec12 = Eigen::Matrix<double, 12, 1>;

Vec12 pack(const StateEci& sat, const StateEci& deb) {
  Vec12 x;
  x << sat.r_eci_m, sat.v_eci_mps, deb.r_eci_m, deb.v_eci_mps;
  return x;
}
StateEci sat_of(const Vec12& x) { return {x.segment<3>(0), x.segment<3>(3)}; }
StateEci deb_of(const Vec12& x) { return {x.segment<3>(6), x.segment<3>(9)}; }

// g = rel_r · rel_v: negative while closing, rising through 0 at a closest approach.
double closing_g(const Vec12& x) {
  return (x.segment<3>(6) - x.segment<3>(0)).dot(x.segment<3>(9) - x.segment<3>(3));
}

bool finite_state(const StateEci& s) { return s.r_eci_m.allFinite() && s.v_eci_mps.allFinite(); }

struct Pending {
  std::int64_t at_us = 0;  // when it takes effect / is delivered
  guidance::AnglesMeasurement meas;
  Vec3 accel = Vec3::Zero();
};

}  // namespace

void SimConfig::validate() const {
  if (!finite_state(satellite0) || !(satellite0.r_eci_m.norm() > 0.0)) {
    throw std::invalid_argument("sim.satellite: state not finite or zero position");
  }
  if (!finite_state(debris0) || !(debris0.r_eci_m.norm() > 0.0)) {
    throw std::invalid_argument("sim.debris: state not finite or zero position");
  }
  std::string err = validate_params(sim_params(), *this, "");
  if (err.empty()) err = guidance.validate();
  if (!err.empty()) throw std::invalid_argument(err);
  integrator.validate();
}

Encounter find_nominal_encounter(const SimConfig& cfg) {
  const GravityModel model = cfg.gravity;
  const EarthModel earth = cfg.earth;
  auto f = [model, earth](double, const Vec12& x) {
    Vec12 d;
    d.head<6>() = orbit_derivative(x.head<6>(), model, earth);
    d.tail<6>() = orbit_derivative(x.tail<6>(), model, earth);
    return d;
  };
  EventOptions eo;
  eo.direction = EventDirection::kRising;
  eo.terminal = true;
  eo.time_tol_s = 1e-10;
  auto g = [](double, const Vec12& x) { return closing_g(x); };
  const auto events = propagate_until_events(f, 0.0, pack(cfg.satellite0, cfg.debris0),
                                             cfg.encounter.search_s, g, cfg.integrator, eo);
  Encounter e;
  if (events.empty()) return e;
  e.found = true;
  e.tca_s = events.front().t_s;
  e.satellite = sat_of(events.front().x);
  e.debris = deb_of(events.front().x);
  e.miss_m = (e.debris.r_eci_m - e.satellite.r_eci_m).norm();
  return e;
}

SimResult run_simulation(const SimConfig& cfg, GuidanceEndpoint& guidance,
                         const SampleCallback& on_sample) {
  cfg.validate();
  const Encounter enc = find_nominal_encounter(cfg);
  if (!enc.found) {
    throw std::runtime_error("sim: no closest approach within encounter_search_s = " +
                             std::to_string(cfg.encounter.search_s) + " s of the epoch");
  }
  SimResult res;
  res.nominal_tca_s = enc.tca_s;
  res.nominal_miss_m = enc.miss_m;
  const double t_start = enc.tca_s - cfg.encounter.detect_before_tca_s;
  res.start_s = t_start;

  Vec3 a_thrust = Vec3::Zero();  // applied acceleration of the satellite (ZOH)
  const GravityModel model = cfg.gravity;
  const EarthModel earth = cfg.earth;
  auto f = [&a_thrust, model, earth](double, const Vec12& x) {
    Vec12 d;
    d.head<6>() = orbit_derivative(x.head<6>(), model, earth);
    d.segment<3>(3) += a_thrust;
    d.tail<6>() = orbit_derivative(x.tail<6>(), model, earth);
    return d;
  };
  Dop853<Vec12> integ(typename Dop853<Vec12>::Rhs(f), cfg.integrator);
  Vec12 x = pack(cfg.satellite0, cfg.debris0);
  if (t_start != 0.0) {  // unforced from the epoch to the detection time
    integ.reset(0.0, x);
    while (integ.t_s() != t_start) {
      if (!integ.step(t_start)) throw std::runtime_error("sim: " + integ.failure_reason());
    }
    x = integ.x();
  }

  AngleSensor sensor(cfg.sensor);
  Actuator actuator(cfg.actuator);
  constexpr std::int64_t kUtime0 = 1'000'000'000;  // utime of the start (arbitrary, > 0)
  const std::int64_t cycle_us = std::llround(1e6 / cfg.guidance.rate_hz);
  const std::int64_t sensor_us = std::llround(1e6 / cfg.sensor.rate_hz);
  const std::int64_t sensor_lat_us = std::llround(cfg.sensor.latency_s * 1e6);
  const std::int64_t act_lat_us = std::llround(cfg.actuator.latency_s * 1e6);
  if (cycle_us < 1 || sensor_us < 1) throw std::invalid_argument("sim: rate too high");
  auto t_of = [&](std::int64_t utime) {
    return t_start + 1e-6 * static_cast<double>(utime - kUtime0);
  };
  const std::int64_t max_us = std::llround(cfg.encounter.max_duration_s * 1e6);

  std::deque<Pending> meas_queue;   // waiting for delivery (sensor latency)
  std::deque<Pending> accel_queue;  // waiting to take effect (actuator latency)
  std::int64_t next_sample_us = kUtime0;
  auto take_sample = [&](std::int64_t utime, const Vec12& xs) {
    guidance::AnglesMeasurement m;
    if (sensor.measure(utime, sat_of(xs), deb_of(xs), &m)) {
      meas_queue.push_back({utime + sensor_lat_us, m, Vec3::Zero()});
    } else {
      ++res.dropouts;
    }
  };
  // Samples due at or before utime_end with the state on [t_a, t_b] of the last step.
  auto take_samples_in_step = [&](std::int64_t utime_end, bool use_dense) {
    while (next_sample_us <= utime_end) {
      const double ts = t_of(next_sample_us);
      if (ts > integ.t_s()) break;
      const Vec12 xs = (use_dense && ts != integ.t_s()) ? integ.dense(ts) : integ.x();
      take_sample(next_sample_us, xs);
      next_sample_us += sensor_us;
    }
  };
  if (next_sample_us == kUtime0) {  // the sample at the start instant
    take_sample(kUtime0, x);
    next_sample_us += sensor_us;
  }

  EventOptions eo;
  eo.direction = EventDirection::kRising;
  eo.time_tol_s = 1e-10;
  auto g = [](double, const Vec12& xs) { return closing_g(xs); };
  bool ca_found = false;
  double t_stop = 0.0;

  for (std::int64_t k = 0;; ++k) {
    const std::int64_t utime = kUtime0 + k * cycle_us;
    if (utime - kUtime0 > max_us) break;
    const double t_k = t_of(utime);
    // Deliver the newest measurement that has arrived.
    const guidance::AnglesMeasurement* meas = nullptr;
    guidance::AnglesMeasurement delivered;
    while (!meas_queue.empty() && meas_queue.front().at_us <= utime) {
      delivered = meas_queue.front().meas;
      meas = &delivered;
      meas_queue.pop_front();
    }
    if (meas != nullptr) ++res.measurements;
    guidance::NavState nav;
    nav.utime_us = utime;
    nav.r_eci_m = x.segment<3>(0);
    nav.v_eci_mps = x.segment<3>(3);
    nav.valid = true;
    const guidance::ThrustCommand cmd = guidance.exchange(utime, nav, meas);
    ++res.cycles;
    accel_queue.push_back({utime + act_lat_us, {}, actuator.accel_eci_mps2(cmd)});
    while (!accel_queue.empty() && accel_queue.front().at_us <= utime) {
      a_thrust = accel_queue.front().accel;
      accel_queue.pop_front();
    }
    if (on_sample) {
      SimSample s;
      s.t_s = t_k;
      s.satellite = sat_of(x);
      s.debris = deb_of(x);
      const Vec3 rr = s.debris.r_eci_m - s.satellite.r_eci_m;
      const Vec3 rv = s.debris.v_eci_mps - s.satellite.v_eci_mps;
      s.range_m = rr.norm();
      s.range_rate_mps = rr.dot(rv) / s.range_m;
      Vec3 u;
      Vec3 ud;
      guidance::los_from_relative(rr, rv, &u, &ud);
      guidance::LosFrame fr;
      if (guidance::los_frame(u, ud, s.satellite.r_eci_m, s.satellite.v_eci_mps, 0.0, &fr)) {
        s.los_rate_true_radps = fr.los_rate_radps;
        s.e_theta_true_eci = fr.e_theta_eci;
      }
      s.has_measurement = (meas != nullptr);
      if (meas != nullptr) s.meas = *meas;
      s.cmd = cmd;
      s.accel_applied_eci_mps2 = a_thrust;
      s.has_status = guidance.status(&s.status);
      on_sample(s);
    }
    // Integrate to the next cycle, in segments split at actuator changes (ZOH).
    const std::int64_t utime_next = utime + cycle_us;
    std::int64_t seg_start_us = utime;
    while (seg_start_us < utime_next && !(ca_found && t_of(seg_start_us) >= t_stop)) {
      std::int64_t seg_end_us = utime_next;
      if (!accel_queue.empty() && accel_queue.front().at_us < seg_end_us) {
        seg_end_us = accel_queue.front().at_us;
      }
      const double t0 = t_of(seg_start_us);
      const double t1 = t_of(seg_end_us);
      integ.reset(t0, x);
      double g_prev = closing_g(x);
      while (integ.t_s() != t1) {
        if (!integ.step(t1)) throw std::runtime_error("sim: " + integ.failure_reason());
        take_samples_in_step(seg_end_us, true);
        const double g_now = closing_g(integ.x());
        if (!ca_found) {
          auto ev = locate_event_in_step(integ, g, g_prev, g_now, eo);
          if (ev) {
            ca_found = true;
            res.closest_approach_found = true;
            res.tca_s = ev->t_s;
            res.miss_m = (ev->x.segment<3>(6) - ev->x.segment<3>(0)).norm();
            t_stop = ev->t_s + cfg.encounter.post_tca_s;
            // Δv and burn time of this segment up to the closest approach.
            const double an = a_thrust.norm();
            if (an > 0.0) {
              res.dv_mps += an * (ev->t_s - t0);
              res.burn_s += ev->t_s - t0;
            }
          }
        }
        g_prev = g_now;
      }
      if (!ca_found) {
        const double an = a_thrust.norm();
        if (an > 0.0) {
          res.dv_mps += an * (t1 - t0);
          res.burn_s += t1 - t0;
        }
      }
      x = integ.x();
      seg_start_us = seg_end_us;
      while (!accel_queue.empty() && accel_queue.front().at_us <= seg_start_us) {
        a_thrust = accel_queue.front().accel;
        accel_queue.pop_front();
      }
    }
    if (ca_found && t_of(utime_next) >= t_stop) break;
  }
  res.has_final_status = guidance.status(&res.final_status);
  return res;
}

}  // namespace evade::sim
