// Real-time closed loop (realtime_simulator.hpp). The loop is event driven on the run's wall
// clock: the next event is the earliest of the next sensor sample, the next measurement
// delivery, the next actuator change and the end of the run; the link blocks until then or
// until a command arrives. Truth (two-body + J2, DOP853, thrust as a zero-order hold with the
// integrator restarted at every change, as in simulator.cpp) is integrated just in time to
// the event, whose outputs are then published. Times are integer µs of the wall clock;
// truth time t = start_s + (utime − start_utime) · 1e-6.
#include "evade/sim/realtime_simulator.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "evade/core/quantile.hpp"
#include "evade/dynamics/events.hpp"
#include "evade/sim/actuator_model.hpp"
#include "evade/sim/sensor_model.hpp"
#include "evade/sim/internal/thrusted_truth.hpp"
#include "evade/sim/truth_sample.hpp"

namespace evade::sim {
namespace {

constexpr std::int64_t kNever = std::numeric_limits<std::int64_t>::max();

struct PendingMeas {
  std::int64_t at_us = 0;  // delivery
  guidance::AnglesMeasurement meas;
};
struct PendingAccel {
  std::int64_t at_us = 0;  // takes effect
  Vec3 accel = Vec3::Zero();
  guidance::ThrustCommand cmd;
};

class RealtimeLoop {
 public:
  RealtimeLoop(const SimConfig& cfg, RealtimeLink& link, const SampleCallback& on_sample,
               RealtimeResult* res)
      : cfg_(cfg),
        link_(link),
        on_sample_(on_sample),
        res_(*res),
        truth_(cfg, &res->sim),
        sensor_(cfg.sensor),
        actuator_(cfg.actuator),
        sample_us_(std::llround(1e6 / cfg.sensor.rate_hz)),
        sensor_lat_us_(std::llround(cfg.sensor.latency_s * 1e6)),
        act_lat_us_(std::llround(cfg.actuator.latency_s * 1e6)),
        late_tol_us_(std::llround(cfg.realtime.late_tolerance_s * 1e6)),
        timeout_us_(std::llround(cfg.realtime.command_timeout_s * 1e6)) {
    if (sample_us_ < 1) throw std::invalid_argument("sim: sensor rate too high");
  }
  RealtimeLoop(const RealtimeLoop&) = delete;
  RealtimeLoop& operator=(const RealtimeLoop&) = delete;

  void run();

 private:
  double t_of(std::int64_t utime) const {
    return res_.sim.start_s + 1e-6 * static_cast<double>(utime - utime0_);
  }
  std::int64_t next_event_us() const;
  void receive_command();
  void advance_truth_to(std::int64_t utime);
  void integrate_segment(std::int64_t seg_start_us, std::int64_t seg_end_us);
  void apply_due_accel(std::int64_t utime);
  void apply_command_timeout(std::int64_t utime);
  void sample_and_deliver(std::int64_t utime);
  void report(std::int64_t utime, const guidance::AnglesMeasurement* meas);
  void account_lateness(std::int64_t utime);
  void finish();

  const SimConfig& cfg_;
  RealtimeLink& link_;
  const SampleCallback& on_sample_;
  RealtimeResult& res_;
  ThrustedTruth truth_;          // truth at truth_us_, thrust in force (ZOH)
  std::int64_t truth_us_ = 0;
  std::int64_t utime0_ = 0;      // wall clock of the run's first instant
  std::int64_t stop_us_ = kNever;  // after the closest approach (+ post_tca_s)
  std::int64_t end_us_ = 0;        // max_duration_s
  AngleSensor sensor_;
  Actuator actuator_;
  const std::int64_t sample_us_, sensor_lat_us_, act_lat_us_, late_tol_us_, timeout_us_;
  std::int64_t cut_at_us_ = kNever;  // the thrust in force is cut then (command timeout)
  std::int64_t next_sample_us_ = 0;
  std::deque<PendingMeas> meas_queue_;
  std::deque<PendingAccel> accel_queue_;
  guidance::ThrustCommand cmd_in_force_;
  std::vector<double> ages_ms_;
};

std::int64_t RealtimeLoop::next_event_us() const {
  std::int64_t ev = std::min({next_sample_us_, stop_us_, end_us_});
  if (!meas_queue_.empty()) ev = std::min(ev, meas_queue_.front().at_us);
  if (!accel_queue_.empty()) ev = std::min(ev, accel_queue_.front().at_us);
  ev = std::min(ev, cut_at_us_);
  return std::max(ev, truth_us_);
}

// The newest command received: it takes effect actuator.latency_s after its receipt, never
// before the truth's present (a command received while truth was being integrated past its
// receipt takes effect at the truth's present). Commands computed before the run started
// (the node was idle) are discarded.
void RealtimeLoop::receive_command() {
  ReceivedCommand rc;
  if (!link_.take_newest_command(&rc)) return;
  if (rc.cmd.utime_us < utime0_) return;
  const std::int64_t at = std::max(rc.received_utime_us + act_lat_us_, truth_us_);
  accel_queue_.push_back({at, actuator_.accel_eci_mps2(rc.cmd), rc.cmd});
}

void RealtimeLoop::apply_due_accel(std::int64_t utime) {
  while (!accel_queue_.empty() && accel_queue_.front().at_us <= utime) {
    const PendingAccel& p = accel_queue_.front();
    truth_.set_thrust(p.accel);
    cmd_in_force_ = p.cmd;
    ages_ms_.push_back(1e-3 * static_cast<double>(p.at_us - p.cmd.utime_us));
    ++res_.commands_applied;
    if (timeout_us_ > 0) cut_at_us_ = p.at_us + timeout_us_;
    accel_queue_.pop_front();
  }
}

// Loss-of-command timeout: no new command took effect for command_timeout_s, so the thrust
// in force is cut (counted once per cut; the next command restores it).
void RealtimeLoop::apply_command_timeout(std::int64_t utime) {
  if (utime < cut_at_us_) return;
  cut_at_us_ = kNever;
  if (truth_.thrust().isZero(0.0)) return;
  truth_.set_thrust(Vec3::Zero());
  ++res_.command_timeouts;
}

// Integrates truth to utime (constant thrust: callers stop at every actuator change).
void RealtimeLoop::advance_truth_to(std::int64_t utime) {
  const std::int64_t end = std::min(utime, stop_us_);
  if (end > truth_us_) integrate_segment(truth_us_, end);
  truth_us_ = std::max(truth_us_, end);
}

void RealtimeLoop::integrate_segment(std::int64_t seg_start_us, std::int64_t seg_end_us) {
  if (!truth_.integrate(t_of(seg_start_us), t_of(seg_end_us), nullptr)) return;
  const double after_s = res_.sim.tca_s - res_.sim.start_s + cfg_.encounter.post_tca_s;
  stop_us_ = std::max(truth_us_, utime0_ + static_cast<std::int64_t>(std::ceil(after_s * 1e6)));
}

// At a sample instant: the navigation state is published and the sensor samples (delivered
// after its latency); then every measurement due by utime is published, stamped with its
// time of validity, exactly as a sensor box would.
void RealtimeLoop::sample_and_deliver(std::int64_t utime) {
  const guidance::AnglesMeasurement* sampled = nullptr;
  guidance::AnglesMeasurement m;
  const bool sample_now = (utime == next_sample_us_);
  if (sample_now) {
    guidance::NavState nav;
    nav.utime_us = utime;
    nav.r_eci_m = truth_.x().segment<3>(0);
    nav.v_eci_mps = truth_.x().segment<3>(3);
    nav.valid = true;
    link_.send_nav(nav);
    if (sensor_.measure(utime, sat_of(truth_.x()), deb_of(truth_.x()), &m)) {
      meas_queue_.push_back({utime + sensor_lat_us_, m});
      sampled = &m;
    } else {
      ++res_.sim.dropouts;
    }
    next_sample_us_ += sample_us_;
  }
  while (!meas_queue_.empty() && meas_queue_.front().at_us <= utime) {
    link_.send_measurement(meas_queue_.front().meas);
    ++res_.sim.measurements;
    meas_queue_.pop_front();
  }
  if (sample_now) report(utime, sampled);  // one history row per sample instant
}

void RealtimeLoop::report(std::int64_t utime, const guidance::AnglesMeasurement* meas) {
  if (!on_sample_) return;
  SimSample s = truth_sample(t_of(utime), sat_of(truth_.x()), deb_of(truth_.x()));
  s.has_measurement = (meas != nullptr);
  if (meas != nullptr) s.meas = *meas;
  s.cmd = cmd_in_force_;
  s.accel_applied_eci_mps2 = truth_.thrust();
  s.has_status = link_.status(&s.status);
  on_sample_(s);
}

// Wall-clock lateness of a step: how long after its due time its outputs left.
void RealtimeLoop::account_lateness(std::int64_t utime) {
  ++res_.steps;
  const std::int64_t late_us = link_.now_us() - utime;
  res_.late_max_ms = std::max(res_.late_max_ms, 1e-3 * static_cast<double>(late_us));
  if (late_us > late_tol_us_) ++res_.late_steps;
}

void RealtimeLoop::finish() {
  res_.sim.cycles = res_.commands_applied;
  res_.commands_received = link_.commands_received();
  res_.commands_discarded_old = link_.commands_discarded_old();
  res_.commands_discarded_malformed = link_.commands_discarded_malformed();
  res_.command_age_ms_p50 = nearest_rank_quantile(ages_ms_, 0.50);
  res_.command_age_ms_p99 = nearest_rank_quantile(ages_ms_, 0.99);
  res_.command_age_ms_max = nearest_rank_quantile(ages_ms_, 1.0);
  res_.sim.has_final_status = link_.status(&res_.sim.final_status);
}

void RealtimeLoop::run() {
  truth_.advance_unforced_to(res_.sim.start_s);  // before the wall clock starts
  // The wall clock starts now (rounded up to the next ms, so that stamps read well).
  utime0_ = (link_.now_us() / 1000 + 1) * 1000;
  res_.start_utime_us = utime0_;
  truth_us_ = next_sample_us_ = utime0_;
  end_us_ = utime0_ + std::llround(cfg_.encounter.max_duration_s * 1e6);
  ReceivedCommand stale;
  while (link_.take_newest_command(&stale)) {
  }
  while (truth_us_ < stop_us_ && truth_us_ < end_us_) {
    const std::int64_t ev = next_event_us();
    if (link_.wait_for_command(ev)) receive_command();
    std::int64_t target = ev;
    if (!accel_queue_.empty()) target = std::min(target, accel_queue_.front().at_us);
    // Woken by a command that is not due yet (actuator latency) or was discarded: wait on.
    if (target > link_.now_us()) continue;
    advance_truth_to(target);
    if (truth_us_ >= stop_us_) break;
    apply_due_accel(truth_us_);
    apply_command_timeout(truth_us_);
    sample_and_deliver(truth_us_);
    account_lateness(truth_us_);
  }
  finish();
}

}  // namespace

RealtimeResult run_realtime_simulation(const SimConfig& cfg, RealtimeLink& link,
                                       const SampleCallback& on_sample) {
  cfg.validate();
  const Encounter enc = find_nominal_encounter(cfg);
  if (!enc.found) {
    throw std::runtime_error("sim: no closest approach within encounter_search_s = " +
                             std::to_string(cfg.encounter.search_s) + " s of the epoch");
  }
  RealtimeResult res;
  res.sim.nominal_tca_s = enc.tca_s;
  res.sim.nominal_miss_m = enc.miss_m;
  res.sim.start_s = enc.tca_s - cfg.encounter.detect_before_tca_s;
  RealtimeLoop loop(cfg, link, on_sample, &res);
  loop.run();
  return res;
}

}  // namespace evade::sim
