// Internal (not installed): one signed ground command's transmissions and the node's answers
// (include/evade/lcm_link/command_uplink.hpp): each transmission signed with the next ARSN of
// the ground's counter, the node's signed answer matched to the transmission it names (key id,
// ARSN and MAC), the counter raised when the node says it is behind; the node's verified status
// and, on request, its verified proposals of one conjunction. Ground code: allocates, throws.
#pragma once

#include <algorithm>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/auth/mac.hpp"
#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/lcm_link/internal/telemetry_watch.hpp"

namespace evade::lcm_link {

double uplink_mono_s();
std::int64_t uplink_realtime_us();
/// The utime a command is stamped with: o.clock_utime() when given, else CLOCK_REALTIME.
std::int64_t uplink_utime(const UplinkOptions& o);

/// The name of a refusal: the detail when there is one (the plan's, the key command's, the
/// conjunction's or the decision's own reason), else the node's input reason.
std::string refusal_name(const evade_cmd_ack_t& a);

class UplinkSession {
 public:
  /// Throws std::invalid_argument for a timeout or interval not > 0 or no counter,
  /// std::runtime_error when LCM cannot start or subscribe.
  UplinkSession(const UplinkOptions& o, const GroundKeys& keys, ArsnSource* arsn);
  ~UplinkSession();
  UplinkSession(const UplinkSession&) = delete;
  UplinkSession& operator=(const UplinkSession&) = delete;

  double left_s() const;
  /// Waits (within the timeout) for a verified status; false if none came.
  bool wait_status(evade_guidance_status_t* out);
  /// Waits (within the timeout) for a verified proposal of event_id; false if none came.
  bool wait_proposal(std::int64_t event_id, evade_cam_proposal_t* out);
  /// Verified proposals seen so far (of any event).
  int proposals_verified() const noexcept { return watch_->proposals_verified; }

  template <typename Msg>
  UplinkResult run(const char* channel, Msg m) {
    UplinkResult r;
    double next_send = uplink_mono_s();
    // Bounded: each pass waits for telemetry or until the next transmission, and the loop ends
    // at the timeout (or at the answer).
    while (left_s() > 0.0 && r.ack_s == 0.0) {
      if (uplink_mono_s() >= next_send) {
        transmit(channel, &m, &r);
        next_send = uplink_mono_s() + o_.retransmit_s;
      }
      handle(std::min(next_send - uplink_mono_s(), left_s()));
      look_at_status();
      if (look_at_acks(&r)) next_send = uplink_mono_s();  // the counter was behind: send at once
    }
    finish(&r);
    return r;
  }

 private:
  void handle(double wait_s);
  void finish(UplinkResult* r) const;

  template <typename Msg>
  void transmit(const char* channel, Msg* m, UplinkResult* r) {
    const std::int64_t a = arsn_->next();  // on disk before it is used
    std::vector<std::uint8_t> buf(static_cast<std::size_t>(m->getEncodedSize()));
    const int n = guidance_lcm::encode_signed(m, channel, keys_.command, a, buf.data(),
                                              static_cast<int>(buf.size()));
    if (n < 0) throw std::runtime_error(std::string("cannot encode the command for ") + channel);
    Sent s{a, {}};
    std::copy(buf.end() - static_cast<long>(auth::kMacBytes), buf.end(), s.mac.begin());
    sent_.push_back(s);
    publish(channel, buf.data(), n);
    if (r->transmissions == 0) r->first_utime = uplink_utime(o_);
    ++r->transmissions;
  }
  void publish(const char* channel, const std::uint8_t* data, int n);

  struct Sent {
    std::int64_t arsn;
    auth::Mac mac;
  };
  const Sent* find_sent(std::int64_t arsn) const;
  void look_at_status();
  bool look_at_acks(UplinkResult* r);
  bool answer(const evade_cmd_ack_t& a, UplinkResult* r);

  struct LcmDeleter {
    void operator()(lcm_t* l) const { lcm_destroy(l); }
  };

  UplinkOptions o_;
  GroundKeys keys_;
  ArsnSource* arsn_;
  std::unique_ptr<TelemetryWatch> watch_;
  std::unique_ptr<lcm_t, LcmDeleter> lcm_;
  lcm_subscription_t* ack_sub_ = nullptr;
  lcm_subscription_t* st_sub_ = nullptr;
  lcm_subscription_t* prop_sub_ = nullptr;
  std::vector<Sent> sent_;
  double t0_ = 0.0;
};

}  // namespace evade::lcm_link
