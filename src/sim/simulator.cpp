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
#include "evade/sim/internal/thrusted_truth.hpp"
#include "evade/sim/truth_sample.hpp"

namespace evade::sim {

namespace {

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
// approach. Holds the truth with its held thrust (ThrustedTruth) and the
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
        truth_(cfg, res),
        sensor_(cfg.sensor),
        actuator_(cfg.actuator) {}
  ClosedLoop(const ClosedLoop&) = delete;
  ClosedLoop& operator=(const ClosedLoop&) = delete;

  void run();

 private:
  void take_sample(std::int64_t utime, const Vec12& xs);
  void take_samples_in_step(std::int64_t utime_end, bool use_dense);
  const guidance::AnglesMeasurement* deliver_measurement(std::int64_t utime);
  guidance::ThrustCommand exchange(std::int64_t utime, const guidance::AnglesMeasurement* meas);
  void apply_due_accel(std::int64_t utime);
  void report(double t_k, const guidance::AnglesMeasurement* meas,
              const guidance::ThrustCommand& cmd);
  void integrate_cycle(std::int64_t utime, std::int64_t utime_next);
  void integrate_segment(std::int64_t seg_start_us, std::int64_t seg_end_us);
  bool stopped_at(std::int64_t utime) const {
    return truth_.closest_approach_found() && sched_.t_of(utime) >= t_stop_;
  }

  const SimConfig& cfg_;
  GuidanceEndpoint& guidance_;
  const SampleCallback& on_sample_;
  SimResult& res_;
  const Schedule sched_;
  ThrustedTruth truth_;  // truth at the start of the current cycle / segment, thrust (ZOH)
  AngleSensor sensor_;
  Actuator actuator_;
  std::deque<Pending> meas_queue_;   // waiting for delivery (sensor latency)
  std::deque<Pending> accel_queue_;  // waiting to take effect (actuator latency)
  std::int64_t next_sample_us_ = kUtime0;
  guidance::AnglesMeasurement delivered_;
  double t_stop_ = 0.0;
};

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
    const Dop853<Vec12>& integ = truth_.integrator();
    if (ts > integ.t_s()) break;
    const Vec12 xs = (use_dense && ts != integ.t_s()) ? integ.dense(ts) : integ.x();
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
  nav.r_eci_m = truth_.x().segment<3>(0);
  nav.v_eci_mps = truth_.x().segment<3>(3);
  nav.valid = true;
  guidance::ThrustCommand cmd = guidance_.exchange(utime, nav, meas);
  ++res_.cycles;
  accel_queue_.push_back({utime + sched_.act_lat_us, {}, actuator_.accel_eci_mps2(cmd)});
  apply_due_accel(utime);
  return cmd;
}

void ClosedLoop::apply_due_accel(std::int64_t utime) {
  while (!accel_queue_.empty() && accel_queue_.front().at_us <= utime) {
    truth_.set_thrust(accel_queue_.front().accel);
    accel_queue_.pop_front();
  }
}

void ClosedLoop::report(double t_k, const guidance::AnglesMeasurement* meas,
                        const guidance::ThrustCommand& cmd) {
  if (!on_sample_) return;
  SimSample s = truth_sample(t_k, sat_of(truth_.x()), deb_of(truth_.x()));
  s.has_measurement = (meas != nullptr);
  if (meas != nullptr) s.meas = *meas;
  s.cmd = cmd;
  s.accel_applied_eci_mps2 = truth_.thrust();
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
  const bool found = truth_.integrate(sched_.t_of(seg_start_us), sched_.t_of(seg_end_us),
                                      [&] { take_samples_in_step(seg_end_us, true); });
  if (found) t_stop_ = res_.tca_s + cfg_.encounter.post_tca_s;
}

void ClosedLoop::run() {
  truth_.advance_unforced_to(sched_.t_start_s);
  if (next_sample_us_ == kUtime0) {  // the sample at the start instant
    take_sample(kUtime0, truth_.x());
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
