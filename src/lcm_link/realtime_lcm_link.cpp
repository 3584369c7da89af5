// make_realtime_lcm_link (realtime_lcm_link.hpp): publishes nav and angles as they are due,
// waits on the LCM socket with select() until the next event or a command, and keeps the
// newest valid command with its receipt time on the link's clock.
#include "evade/lcm_link/realtime_lcm_link.hpp"

#include <sys/select.h>
#include <time.h>

#include <cerrno>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include <lcm/lcm.h>

#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/convert.hpp"
#include "evade/guidance_lcm/internal/raw_publisher.hpp"
#include "evade/lcm_link/internal/command_filter.hpp"
#include "evade/lcm_link/internal/status_watch.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::lcm_link {
namespace {

using namespace evade::guidance_lcm;

std::int64_t clock_us(clockid_t clk) {
  timespec ts{};
  clock_gettime(clk, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

class RealtimeLcmLink final : public sim::RealtimeLink {
 public:
  RealtimeLcmLink(const std::string& url, const guidance_lcm::SigningKey& sensor_key)
      : url_(url),
        lcm_(lcm_create(url.empty() ? nullptr : url.c_str())),
        offset_us_(clock_us(CLOCK_REALTIME) - clock_us(CLOCK_MONOTONIC)) {
    if (lcm_ == nullptr) throw std::runtime_error("evade sim: cannot open LCM URL '" + url + "'");
    nav_pub_ = std::make_unique<SigningPublisher<evade_nav_state_t>>(lcm_, kChanNav);
    ang_pub_ = std::make_unique<SigningPublisher<evade_angles_t>>(lcm_, kChanAngles);
    nav_pub_->set_signing_key(sensor_key);
    ang_pub_->set_signing_key(sensor_key);
    cmd_sub_ = lcm_subscribe(lcm_, kChanCmd, &RealtimeLcmLink::on_cmd, this);
    st_sub_ = lcm_subscribe(lcm_, kChanStatus, &StatusWatch::on_status, &status_);
    if (cmd_sub_ == nullptr || st_sub_ == nullptr)
      throw std::runtime_error("evade sim: cannot subscribe on LCM URL '" + url + "'");
  }
  ~RealtimeLcmLink() override {
    lcm_unsubscribe(lcm_, cmd_sub_);
    lcm_unsubscribe(lcm_, st_sub_);
    lcm_destroy(lcm_);
  }

  std::int64_t now_us() override { return clock_us(CLOCK_MONOTONIC) + offset_us_; }

  bool wait_for_command(std::int64_t until_utime_us) override {
    const int fd = lcm_get_fileno(lcm_);
    while (!have_new_) {
      const std::int64_t left_us = until_utime_us - now_us();
      if (left_us <= 0) return false;
      fd_set fds;
      FD_ZERO(&fds);
      FD_SET(fd, &fds);
      timeval tv{};
      tv.tv_sec = static_cast<time_t>(left_us / 1000000);
      tv.tv_usec = static_cast<suseconds_t>(left_us % 1000000);
      const int rc = select(fd + 1, &fds, nullptr, nullptr, &tv);
      if (rc < 0 && errno != EINTR)
        throw std::runtime_error("evade sim: select on LCM URL '" + url_ + "' failed");
      if (rc > 0 && lcm_handle_timeout(lcm_, 0) < 0)
        throw std::runtime_error("evade sim: LCM receive failed on '" + url_ + "'");
    }
    return true;
  }

  bool take_newest_command(sim::ReceivedCommand* out) override {
    if (!have_new_) return false;
    *out = newest_;
    have_new_ = false;
    return true;
  }

  void send_nav(const guidance::NavState& nav) override {
    to_lcm(nav, ++nav_seq_, &nav_msg_);
    if (nav_pub_->publish(nav_msg_) != 0) fail("EVADE_NAV");
  }
  void send_measurement(const guidance::AnglesMeasurement& meas) override {
    to_lcm(meas, ++ang_seq_, &ang_msg_);
    if (ang_pub_->publish(ang_msg_) != 0) fail("EVADE_ANGLES");
  }
  bool status(guidance::GuidanceStatus* out) const override {
    if (!status_.have) return false;
    from_lcm(status_.last, out);
    return true;
  }
  long commands_received() const override { return received_; }
  long commands_discarded_old() const override { return discarded_old_; }
  long commands_discarded_malformed() const override { return discarded_malformed_; }

 private:
  [[noreturn]] void fail(const char* what) const {
    throw std::runtime_error(std::string("evade sim: LCM publish of ") + what + " failed on '" +
                             url_ + "'");
  }
  static void on_cmd(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<RealtimeLcmLink*>(user);
    const std::int64_t t = self->now_us();
    bool have = self->received_ > 0;
    const CommandVerdict v = receive_command(rbuf, &have, &self->last_seq_, &self->newest_.cmd);
    if (v != CommandVerdict::kAccepted) {
      ++(v == CommandVerdict::kOld ? self->discarded_old_ : self->discarded_malformed_);
      return;
    }
    ++self->received_;
    self->newest_.received_utime_us = t;
    self->have_new_ = true;
  }

  std::string url_;
  lcm_t* lcm_;
  std::int64_t offset_us_;  // CLOCK_REALTIME − CLOCK_MONOTONIC at construction
  std::unique_ptr<SigningPublisher<evade_nav_state_t>> nav_pub_;
  std::unique_ptr<SigningPublisher<evade_angles_t>> ang_pub_;
  lcm_subscription_t* cmd_sub_ = nullptr;
  lcm_subscription_t* st_sub_ = nullptr;
  evade_nav_state_t nav_msg_{};
  evade_angles_t ang_msg_{};
  std::int64_t nav_seq_ = 0, ang_seq_ = 0;
  sim::ReceivedCommand newest_{};
  bool have_new_ = false;
  long received_ = 0;
  long discarded_old_ = 0, discarded_malformed_ = 0;
  std::int64_t last_seq_ = 0;
  StatusWatch status_;  // the node's newest status
};

}  // namespace

std::unique_ptr<sim::RealtimeLink> make_realtime_lcm_link(const std::string& lcm_url,
                                                          const guidance_lcm::SigningKey& sensor_key) {
  return std::make_unique<RealtimeLcmLink>(lcm_url, sensor_key);
}

}  // namespace evade::lcm_link
