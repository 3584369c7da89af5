// The simulator's link to evade_guidance_node over LCM (make_lcm_endpoint, declared in
// evade/lcm_link/sim_lcm_endpoint.hpp). Per guidance cycle it publishes evade_nav_state_t,
// the measurement (evade_angles_t, if one was delivered this cycle) and then the
// evade_sim_clock_t tick; in lockstep it waits for the node's evade_thrust_cmd_t whose utime
// equals the tick's and returns it, so the run is deterministic and equals the in-process run
// bit for bit (docs/GUIDANCE_NODE.md NODE-LS-1). Commands are validated before use
// (NODE-IN-2): a malformed command is an error, never thrust.
// Pacing: a lockstep run goes as fast as the node answers (~10^4 messages/s), which is more
// than lcm-logger can record without losing datagrams. For a recorded HIL run, set
// EVADE_SIM_LCM_REALTIME_FACTOR=F (> 0): tick k is then sent no earlier than k*dt/F of wall
// time after the first (F = 1: real time). Unset: unpaced.
#include <time.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

#include <lcm/lcm.h>

#include "evade/lcm_link/internal/status_watch.hpp"
#include "evade/lcm_link/internal/command_filter.hpp"
#include "evade/lcm_link/sim_lcm_endpoint.hpp"

#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/raw_publisher.hpp"
#include "evade/guidance_lcm/validate.hpp"
#include "evade/evade_sim_clock_t.hpp"

namespace evade::lcm_link {
namespace {

using namespace evade;
using namespace evade::guidance_lcm;

std::int64_t mono_us() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

class LcmEndpoint final : public sim::GuidanceEndpoint {
 public:
  LcmEndpoint(const std::string& url, bool lockstep, double timeout_s,
              const guidance_lcm::SigningKey& sensor_key)
      : url_(url),
        lcm_(lcm_create(url.empty() ? nullptr : url.c_str())),
        lockstep_(lockstep),
        timeout_us_(static_cast<std::int64_t>(timeout_s * 1e6)) {
    if (lcm_ == nullptr) throw std::runtime_error("evade sim: cannot open LCM URL '" + url + "'");
    if (const char* f = std::getenv("EVADE_SIM_LCM_REALTIME_FACTOR")) {
      char* end = nullptr;
      pace_factor_ = std::strtod(f, &end);
      if (end == f || *end != '\0' || !(pace_factor_ > 0.0) || !(pace_factor_ <= 1e6)) {
        lcm_destroy(lcm_);  // the destructor does not run when the constructor throws
        throw std::invalid_argument(std::string("EVADE_SIM_LCM_REALTIME_FACTOR = '") + f +
                                    "': must be a number in (0, 1e6]");
      }
    }
    nav_pub_ = std::make_unique<SigningPublisher<evade_nav_state_t>>(lcm_, kChanNav);
    ang_pub_ = std::make_unique<SigningPublisher<evade_angles_t>>(lcm_, kChanAngles);
    clk_pub_ = std::make_unique<SigningPublisher<evade_sim_clock_t>>(lcm_, kChanClock);
    nav_pub_->set_signing_key(sensor_key);
    ang_pub_->set_signing_key(sensor_key);
    clk_pub_->set_signing_key(sensor_key);
    cmd_sub_ = lcm_subscribe(lcm_, kChanCmd, &LcmEndpoint::on_cmd, this);
    st_sub_ = lcm_subscribe(lcm_, kChanStatus, &StatusWatch::on_status, &status_);
    if (cmd_sub_ == nullptr || st_sub_ == nullptr) {
      lcm_destroy(lcm_);
      throw std::runtime_error("evade sim: cannot subscribe on LCM URL '" + url + "'");
    }
  }
  ~LcmEndpoint() override {
    lcm_unsubscribe(lcm_, cmd_sub_);
    lcm_unsubscribe(lcm_, st_sub_);
    lcm_destroy(lcm_);
  }

  guidance::ThrustCommand exchange(std::int64_t utime_us, const guidance::NavState& nav,
                                   const guidance::AnglesMeasurement* meas) override {
    to_lcm(nav, ++nav_seq_, &nav_msg_);
    have_meas_ = meas != nullptr;
    if (have_meas_) to_lcm(*meas, ++ang_seq_, &ang_msg_);
    clk_msg_.utime = utime_us;
    clk_msg_.seq = ++clk_seq_;
    pace(utime_us);
    send_cycle();
    if (!lockstep_) {
      handle_ready();
      return latest_;
    }
    // Lockstep: wait for the command of this tick. Without an answer the cycle is re-sent
    // every 200 ms: the node may still be subscribing, or have dropped the tick (a burst that
    // spent the clock's verification budget: docs/SECURITY.md AUTH-5); re-sent messages carry
    // the same seq, so the node counts any duplicate as stale.
    const std::int64_t deadline = mono_us() + timeout_us_;
    std::int64_t resend_at = mono_us() + 200000;
    while (!(have_cmd_ && latest_.utime_us == utime_us)) {
      const std::int64_t now = mono_us();
      if (now >= deadline) {
        std::ostringstream os;
        os << "evade sim: no command from evade_guidance_node for tick utime " << utime_us
           << " within " << 1e-6 * static_cast<double>(timeout_us_) << " s on LCM URL '" << url_
           << "' (is the node running with --lockstep on the same URL?)";
        throw std::runtime_error(os.str());
      }
      if (now >= resend_at) {
        send_cycle();
        resend_at = now + 200000;
      }
      const std::int64_t wait_us = std::min(deadline, resend_at) - now;
      wait(static_cast<int>((wait_us + 999) / 1000));
    }
    // The node publishes its status right after the command; when it does so every cycle,
    // wait for it too so status() describes this cycle.
    if (status_every_cycle_) {
      const std::int64_t st_deadline = mono_us() + 200000;
      while (!(status_.have && status_.last.utime == utime_us) && mono_us() < st_deadline) wait(10);
      status_every_cycle_ = status_.have && status_.last.utime == utime_us;
    } else {
      handle_ready();
      status_every_cycle_ = status_.have && status_.last.utime == utime_us;
    }
    return latest_;
  }

  bool status(guidance::GuidanceStatus* out) const override {
    if (!status_.have) return false;
    from_lcm(status_.last, out);
    return true;
  }

 private:
  void pace(std::int64_t utime_us) {
    if (pace_factor_ <= 0.0) return;
    if (!paced_once_) {
      paced_once_ = true;
      pace_wall0_us_ = mono_us();
      pace_sim0_us_ = utime_us;
      return;
    }
    const std::int64_t due = pace_wall0_us_ + static_cast<std::int64_t>(
        static_cast<double>(utime_us - pace_sim0_us_) / pace_factor_);
    const std::int64_t now = mono_us();
    if (due > now) {
      timespec ts{};
      ts.tv_sec = static_cast<time_t>((due - now) / 1000000);
      ts.tv_nsec = static_cast<long>((due - now) % 1000000) * 1000;
      nanosleep(&ts, nullptr);
    }
  }
  void send_cycle() {
    nav_pub_->publish(nav_msg_);
    if (have_meas_) ang_pub_->publish(ang_msg_);
    clk_pub_->publish(clk_msg_);
  }
  void handle_ready() {
    while (lcm_handle_timeout(lcm_, 0) > 0) {
    }
  }
  void wait(int ms) {
    if (lcm_handle_timeout(lcm_, ms < 1 ? 1 : ms) < 0)
      throw std::runtime_error("evade sim: LCM receive failed on '" + url_ + "'");
  }
  static void on_cmd(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<LcmEndpoint*>(user);
    if (receive_command(rbuf, &self->have_cmd_, &self->last_cmd_seq_, &self->latest_) ==
        CommandVerdict::kMalformed) {
      ++self->bad_cmds_;  // the previous command stays in force
    }
  }

  std::string url_;
  lcm_t* lcm_;
  bool lockstep_;
  std::int64_t timeout_us_;
  std::unique_ptr<SigningPublisher<evade_nav_state_t>> nav_pub_;
  std::unique_ptr<SigningPublisher<evade_angles_t>> ang_pub_;
  std::unique_ptr<SigningPublisher<evade_sim_clock_t>> clk_pub_;
  lcm_subscription_t* cmd_sub_ = nullptr;
  lcm_subscription_t* st_sub_ = nullptr;
  evade_nav_state_t nav_msg_{};
  evade_angles_t ang_msg_{};
  evade_sim_clock_t clk_msg_{};
  bool have_meas_ = false;
  std::int64_t nav_seq_ = 0, ang_seq_ = 0, clk_seq_ = 0;
  guidance::ThrustCommand latest_{};  // zero thrust until the node has spoken
  bool have_cmd_ = false;
  std::int64_t last_cmd_seq_ = 0;
  StatusWatch status_;  // the node's newest status
  bool status_every_cycle_ = true;
  long bad_cmds_ = 0;
  double pace_factor_ = 0.0;  // 0: unpaced
  bool paced_once_ = false;
  std::int64_t pace_wall0_us_ = 0;
  std::int64_t pace_sim0_us_ = 0;
};

}  // namespace

std::unique_ptr<sim::GuidanceEndpoint> make_lcm_endpoint(
    const std::string& lcm_url, bool lockstep, double timeout_s,
    const guidance_lcm::SigningKey& sensor_key) {
  if (!(timeout_s > 0.0))
    throw std::invalid_argument("--lcm-timeout-s must be > 0");
  return std::make_unique<LcmEndpoint>(lcm_url, lockstep, timeout_s, sensor_key);
}

}  // namespace evade::lcm_link
