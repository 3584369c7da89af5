// Closed-loop close-range evasion simulation (paper 000 sec. 4): truth with two-body + J2
// (Vallado eq. 8-30 via the dynamics module) integrated by DOP853 (HNW I sec. II.10) for both
// objects at once, thrust as a zero-order hold between command changes (the integrator is
// restarted at every change so no step straddles a discontinuity), closest approach located
// as the rising zero of g = (r_d − r_s)·(v_d − v_s) on the dense output (Brent).
// Steps of run_simulation: nominal_start (checks, unforced encounter, start time), then per
// guidance cycle (ClosedLoop::run) the sensor delivery, one guidance exchange with the
// actuator's ZOH update, the history sample, and the integration to the next cycle in
// constant-thrust segments with the closest-approach event and the Δv / burn-time tally.
#include "evade/sim/simulator.hpp"

#include <cmath>
#include <deque>
#include <stdexcept>
#include <string>

#include "evade/dynamics/events.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/sim/actuator_model.hpp"
#include "evade/sim/sensor_model.hpp"
#include "evade/sim/truth_sample.hpp"

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

struct Pending {
  std::int64_t at_us = 0;  // when it takes effect / is delivered
  guidance::AnglesMeasurement meas;
  Vec3 accel = Vec3::Zero();
};

}  // namespace

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

namespace {

constexpr std::int64_t kUtime0 = 1'000'000'000;  // utime of the start (arbitrary, > 0)

// The run's clock: guidance cycles, sensor samples and latencies on an integer µs grid that
// starts at kUtime0 (= t_start_s from the epoch), so cycles and samples never drift apart.
struct Schedule {
  double t_start_s = 0.0;
  std::int64_t cycle_us = 0;      // guidance cycle
  std::int64_t sensor_us = 0;     // sensor sample interval
  std::int64_t sensor_lat_us = 0;
  std::int64_t act_lat_us = 0;
  std::int64_t max_us = 0;        // give up after this long

  double t_of(std::int64_t utime) const {
    return t_start_s + 1e-6 * static_cast<double>(utime - kUtime0);
  }
};

Schedule make_schedule(const SimConfig& cfg, double t_start_s) {
  Schedule s;
  s.t_start_s = t_start_s;
  s.cycle_us = std::llround(1e6 / cfg.guidance.rate_hz);
  s.sensor_us = std::llround(1e6 / cfg.sensor.rate_hz);
  s.sensor_lat_us = std::llround(cfg.sensor.latency_s * 1e6);
  s.act_lat_us = std::llround(cfg.actuator.latency_s * 1e6);
  if (s.cycle_us < 1 || s.sensor_us < 1) throw std::invalid_argument("sim: rate too high");
  s.max_us = std::llround(cfg.encounter.max_duration_s * 1e6);
  return s;
}

// Validates cfg and finds the unforced closest approach; the run starts detect_before_tca_s
// before it.
SimResult nominal_start(const SimConfig& cfg) {
  cfg.validate();
  const Encounter enc = find_nominal_encounter(cfg);
  if (!enc.found) {
    throw std::runtime_error("sim: no closest approach within encounter_search_s = " +
                             std::to_string(cfg.encounter.search_s) + " s of the epoch");
  }
  SimResult res;
  res.nominal_tca_s = enc.tca_s;
  res.nominal_miss_m = enc.miss_m;
  res.start_s = enc.tca_s - cfg.encounter.detect_before_tca_s;
  return res;
}

// One closed-loop run from the start instant: per guidance cycle, deliver the newest
// measurement, exchange with the guidance, queue the actuator's acceleration, report the
// sample, then integrate to the next cycle in ZOH segments while looking for the closest
// approach. Holds the truth, the integrator (its right-hand side reads a_thrust_) and the
// sensor/actuator queues; not copyable.
class ClosedLoop {
 public:
  ClosedLoop(const SimConfig& cfg, GuidanceEndpoint& guidance, const SampleCallback& on_sample,
             SimResult* res)
      : cfg_(cfg),
        guidance_(guidance),
        on_sample_(on_sample),
        res_(*res),
        sched_(make_schedule(cfg, res->start_s)),
        integ_(typename Dop853<Vec12>::Rhs(
                   [this](double, const Vec12& x) { return derivative(x); }),
               cfg.integrator),
        x_(pack(cfg.satellite0, cfg.debris0)),
        sensor_(cfg.sensor),
        actuator_(cfg.actuator) {
    eo_.direction = EventDirection::kRising;
    eo_.time_tol_s = 1e-10;
  }
  ClosedLoop(const ClosedLoop&) = delete;
  ClosedLoop& operator=(const ClosedLoop&) = delete;

  void run();

 private:
  Vec12 derivative(const Vec12& x) const;
  void advance_unforced_to_start();
  void take_sample(std::int64_t utime, const Vec12& xs);
  void take_samples_in_step(std::int64_t utime_end, bool use_dense);
  const guidance::AnglesMeasurement* deliver_measurement(std::int64_t utime);
  guidance::ThrustCommand exchange(std::int64_t utime, const guidance::AnglesMeasurement* meas);
  void apply_due_accel(std::int64_t utime);
  void report(double t_k, const guidance::AnglesMeasurement* meas,
              const guidance::ThrustCommand& cmd);
  void integrate_cycle(std::int64_t utime, std::int64_t utime_next);
  void integrate_segment(std::int64_t seg_start_us, std::int64_t seg_end_us);
  void check_closest_approach(double g_prev, double g_now, double t0);
  void add_thrust_time(double dt_s);
  bool stopped_at(std::int64_t utime) const {
    return ca_found_ && sched_.t_of(utime) >= t_stop_;
  }

  const SimConfig& cfg_;
  GuidanceEndpoint& guidance_;
  const SampleCallback& on_sample_;
  SimResult& res_;
  const Schedule sched_;
  Vec3 a_thrust_ = Vec3::Zero();  // applied acceleration of the satellite (ZOH)
  Dop853<Vec12> integ_;
  Vec12 x_;  // truth at the start of the current cycle / segment
  AngleSensor sensor_;
  Actuator actuator_;
  std::deque<Pending> meas_queue_;   // waiting for delivery (sensor latency)
  std::deque<Pending> accel_queue_;  // waiting to take effect (actuator latency)
  std::int64_t next_sample_us_ = kUtime0;
  guidance::AnglesMeasurement delivered_;
  EventOptions eo_;
  bool ca_found_ = false;
  double t_stop_ = 0.0;
};

Vec12 ClosedLoop::derivative(const Vec12& x) const {
  Vec12 d;
  d.head<6>() = orbit_derivative(x.head<6>(), cfg_.gravity, cfg_.earth);
  d.segment<3>(3) += a_thrust_;
  d.tail<6>() = orbit_derivative(x.tail<6>(), cfg_.gravity, cfg_.earth);
  return d;
}

// Unforced from the epoch to the detection time.
void ClosedLoop::advance_unforced_to_start() {
  const double t_start = sched_.t_start_s;
  if (t_start == 0.0) return;
  integ_.reset(0.0, x_);
  while (integ_.t_s() != t_start) {
    if (!integ_.step(t_start)) throw std::runtime_error("sim: " + integ_.failure_reason());
  }
  x_ = integ_.x();
}

void ClosedLoop::take_sample(std::int64_t utime, const Vec12& xs) {
  guidance::AnglesMeasurement m;
  if (sensor_.measure(utime, sat_of(xs), deb_of(xs), &m)) {
    meas_queue_.push_back({utime + sched_.sensor_lat_us, m, Vec3::Zero()});
  } else {
    ++res_.dropouts;
  }
}

// Samples due at or before utime_end with the state on [t_a, t_b] of the last step.
void ClosedLoop::take_samples_in_step(std::int64_t utime_end, bool use_dense) {
  while (next_sample_us_ <= utime_end) {
    const double ts = sched_.t_of(next_sample_us_);
    if (ts > integ_.t_s()) break;
    const Vec12 xs = (use_dense && ts != integ_.t_s()) ? integ_.dense(ts) : integ_.x();
    take_sample(next_sample_us_, xs);
    next_sample_us_ += sched_.sensor_us;
  }
}

// The newest measurement that has arrived by utime (nullptr: none).
const guidance::AnglesMeasurement* ClosedLoop::deliver_measurement(std::int64_t utime) {
  const guidance::AnglesMeasurement* meas = nullptr;
  while (!meas_queue_.empty() && meas_queue_.front().at_us <= utime) {
    delivered_ = meas_queue_.front().meas;
    meas = &delivered_;
    meas_queue_.pop_front();
  }
  if (meas != nullptr) ++res_.measurements;
  return meas;
}

// One guidance exchange with the true navigation state; its acceleration is queued behind
// the actuator latency and whatever is due now takes effect.
guidance::ThrustCommand ClosedLoop::exchange(std::int64_t utime,
                                             const guidance::AnglesMeasurement* meas) {
  guidance::NavState nav;
  nav.utime_us = utime;
  nav.r_eci_m = x_.segment<3>(0);
  nav.v_eci_mps = x_.segment<3>(3);
  nav.valid = true;
  const guidance::ThrustCommand cmd = guidance_.exchange(utime, nav, meas);
  ++res_.cycles;
  accel_queue_.push_back({utime + sched_.act_lat_us, {}, actuator_.accel_eci_mps2(cmd)});
  apply_due_accel(utime);
  return cmd;
}

void ClosedLoop::apply_due_accel(std::int64_t utime) {
  while (!accel_queue_.empty() && accel_queue_.front().at_us <= utime) {
    a_thrust_ = accel_queue_.front().accel;
    accel_queue_.pop_front();
  }
}

void ClosedLoop::report(double t_k, const guidance::AnglesMeasurement* meas,
                        const guidance::ThrustCommand& cmd) {
  if (!on_sample_) return;
  SimSample s = truth_sample(t_k, sat_of(x_), deb_of(x_));
  s.has_measurement = (meas != nullptr);
  if (meas != nullptr) s.meas = *meas;
  s.cmd = cmd;
  s.accel_applied_eci_mps2 = a_thrust_;
  s.has_status = guidance_.status(&s.status);
  on_sample_(s);
}

// Integrates to the next cycle, in segments split at actuator changes (ZOH).
void ClosedLoop::integrate_cycle(std::int64_t utime, std::int64_t utime_next) {
  std::int64_t seg_start_us = utime;
  while (seg_start_us < utime_next && !stopped_at(seg_start_us)) {
    std::int64_t seg_end_us = utime_next;
    if (!accel_queue_.empty() && accel_queue_.front().at_us < seg_end_us) {
      seg_end_us = accel_queue_.front().at_us;
    }
    integrate_segment(seg_start_us, seg_end_us);
    seg_start_us = seg_end_us;
    apply_due_accel(seg_start_us);
  }
}

// One segment at constant thrust: sensor samples on the dense output, the closest approach
// as the rising zero of g, and Δv / burn time up to the closest approach.
void ClosedLoop::integrate_segment(std::int64_t seg_start_us, std::int64_t seg_end_us) {
  const double t0 = sched_.t_of(seg_start_us);
  const double t1 = sched_.t_of(seg_end_us);
  integ_.reset(t0, x_);
  double g_prev = closing_g(x_);
  while (integ_.t_s() != t1) {
    if (!integ_.step(t1)) throw std::runtime_error("sim: " + integ_.failure_reason());
    take_samples_in_step(seg_end_us, true);
    const double g_now = closing_g(integ_.x());
    if (!ca_found_) check_closest_approach(g_prev, g_now, t0);
    g_prev = g_now;
  }
  if (!ca_found_) add_thrust_time(t1 - t0);
  x_ = integ_.x();
}

void ClosedLoop::check_closest_approach(double g_prev, double g_now, double t0) {
  auto g = [](double, const Vec12& xs) { return closing_g(xs); };
  auto ev = locate_event_in_step(integ_, g, g_prev, g_now, eo_);
  if (!ev) return;
  ca_found_ = true;
  res_.closest_approach_found = true;
  res_.tca_s = ev->t_s;
  res_.miss_m = (ev->x.segment<3>(6) - ev->x.segment<3>(0)).norm();
  t_stop_ = ev->t_s + cfg_.encounter.post_tca_s;
  // Δv and burn time of this segment up to the closest approach.
  add_thrust_time(ev->t_s - t0);
}

void ClosedLoop::add_thrust_time(double dt_s) {
  const double an = a_thrust_.norm();
  if (an > 0.0) {
    res_.dv_mps += an * dt_s;
    res_.burn_s += dt_s;
  }
}

void ClosedLoop::run() {
  advance_unforced_to_start();
  if (next_sample_us_ == kUtime0) {  // the sample at the start instant
    take_sample(kUtime0, x_);
    next_sample_us_ += sched_.sensor_us;
  }
  for (std::int64_t k = 0;; ++k) {
    const std::int64_t utime = kUtime0 + k * sched_.cycle_us;
    if (utime - kUtime0 > sched_.max_us) break;
    const double t_k = sched_.t_of(utime);
    const guidance::AnglesMeasurement* meas = deliver_measurement(utime);
    const guidance::ThrustCommand cmd = exchange(utime, meas);
    report(t_k, meas, cmd);
    const std::int64_t utime_next = utime + sched_.cycle_us;
    integrate_cycle(utime, utime_next);
    if (stopped_at(utime_next)) break;
  }
  res_.has_final_status = guidance_.status(&res_.final_status);
}

}  // namespace

SimResult run_simulation(const SimConfig& cfg, GuidanceEndpoint& guidance,
                         const SampleCallback& on_sample) {
  SimResult res = nominal_start(cfg);
  ClosedLoop loop(cfg, guidance, on_sample, &res);
  loop.run();
  return res;
}

}  // namespace evade::sim
