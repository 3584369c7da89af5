// Test harness for the node's command path (docs/SECURITY.md AUTH-*, ARSN-*, TM-*): plans and
// other commands as the ground signs them or as an attacker forges them, cycles with nav only
// (the law stays STANDBY, so any thrust is the plan's), the accounting identity, a scratch
// directory for state files, and a recorder of the node's acknowledgements that verifies each
// under the telemetry key exactly as the ground does (auth::mac_valid on the channel name).
#pragma once

#include <stdlib.h>
#include <unistd.h>

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "evade/auth/trailer.hpp"
#include "evade/guidance_lcm/burn_plan_convert.hpp"
#include "node_harness.hpp"

namespace evade::guidance_lcm::test {

inline constexpr std::int64_t kT0 = 1'000'000'000;  // first cycle [us]

/// One impulse of dv (default 0.1 m/s along track) at t_s after kT0: 5 cycles at 1 m/s^2.
inline evade_burn_plan_t plan_msg(std::int64_t seq, double t_s = 1.0,
                                  Vec3 dv = Vec3(0.0, 0.1, 0.0), std::int64_t utime = kT0) {
  BurnPlan p;
  p.plan_id = seq;
  p.n_impulses = 1;
  p.impulses[0].t_s = t_s;
  p.impulses[0].dv_rsw_mps = dv;
  evade_burn_plan_t m{};
  to_lcm(p, utime, seq, kT0, guidance::PlanFrame::kRsw, &m);
  return m;
}

/// Encodes m signed with key and arsn for sign_channel (not necessarily where it is sent).
template <typename Msg>
std::vector<std::uint8_t> signed_bytes(Msg m, const char* sign_channel, const SigningKey& key,
                                       std::int64_t arsn) {
  std::vector<std::uint8_t> b(static_cast<std::size_t>(m.getEncodedSize()));
  const int n = encode_signed(&m, sign_channel, key, arsn, b.data(), static_cast<int>(b.size()));
  EXPECT_EQ(n, static_cast<int>(b.size()));
  return b;
}

inline void send(Rig& rig, const char* channel, const std::vector<std::uint8_t>& b) {
  rig.pub.send_bytes(channel, b.data(), static_cast<unsigned>(b.size()));
}

/// Nav only (no angles: the law stays STANDBY) at cycle k; returns the command.
inline const evade_thrust_cmd_t& nav_cycle(Rig& rig, int k) {
  const std::int64_t t = kT0 + k * kPeriodUs;
  evade_nav_state_t nav{};
  rig.enc.nav_at(t, &nav);
  nav.seq = k + 1;
  rig.pub.send(kChanNav, nav);
  return rig.cycle(t);
}

/// Runs cycles [k0, k1) and returns how many commanded thrust.
inline int thrust_cycles(Rig& rig, int k0, int k1) {
  int n = 0;
  for (int k = k0; k < k1; ++k) n += nav_cycle(rig, k).accel_mps2 > 0.0 ? 1 : 0;
  return n;
}

inline std::int64_t reason(const Rig& rig, Reason r) {
  return rig.node.counts().by_reason[static_cast<int>(r)];
}

/// NODE-IN-1: every message received is in exactly one outcome.
inline void expect_accounted(const Rig& rig) {
  EXPECT_EQ(rig.node.counts().received, rig.node.counts().accounted());
}

/// A scratch directory (mode 0700) for state files, removed with its contents.
struct TempDir {
  TempDir() {
    char tmpl[] = "/tmp/evade-auth-XXXXXX";
    const char* d = mkdtemp(tmpl);
    path = d != nullptr ? d : "";
  }
  ~TempDir() {
    for (const char* f : {"/state", "/state.tmp", "/target"}) (void)std::remove((path + f).c_str());
    (void)rmdir(path.c_str());
  }
  std::string path;
};

/// Every acknowledgement the node publishes on EVADE_CMD_ACK (memq delivers on the next
/// drain), verified under the telemetry key as the ground verifies it.
class AckRecorder {
 public:
  explicit AckRecorder(lcm_t* lcm, SigningKey telemetry = test_telemetry_key())
      : lcm_(lcm), key_(telemetry) {
    sub_ = lcm_subscribe(lcm, kChanCmdAck, &AckRecorder::on_ack, this);
  }
  ~AckRecorder() { lcm_unsubscribe(lcm_, sub_); }
  AckRecorder(const AckRecorder&) = delete;
  AckRecorder& operator=(const AckRecorder&) = delete;

  const std::vector<evade_cmd_ack_t>& acks() const { return acks_; }
  int unverified() const { return unverified_; }
  /// The acknowledgement naming (key_id, arsn), or nullptr.
  const evade_cmd_ack_t* find(std::int32_t key_id, std::int64_t arsn) const {
    for (const evade_cmd_ack_t& a : acks_) {
      if (a.cmd_key_id == key_id && a.cmd_arsn == arsn) return &a;
    }
    return nullptr;
  }

 private:
  static void on_ack(const lcm_recv_buf_t* rbuf, const char* channel, void* user) {
    auto* self = static_cast<AckRecorder*>(user);
    const auto* d = static_cast<const std::uint8_t*>(rbuf->data);
    auth::TrailerView t;
    evade_cmd_ack_t a{};
    const bool ok = auth::read_trailer(d, rbuf->data_size, &t) && t.key_id == self->key_.id &&
                    auth::mac_valid(self->key_.key, channel, d, rbuf->data_size) &&
                    a.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) ==
                        static_cast<int>(rbuf->data_size);
    if (!ok) {
      ++self->unverified_;
      return;
    }
    self->acks_.push_back(a);
  }
  lcm_t* lcm_;
  SigningKey key_;
  lcm_subscription_t* sub_ = nullptr;
  std::vector<evade_cmd_ack_t> acks_;
  int unverified_ = 0;
};

/// The MAC of signed bytes (the last 32), as the acknowledgement names it.
inline bool names_mac(const evade_cmd_ack_t& a, const std::vector<std::uint8_t>& b) {
  for (std::size_t i = 0; i < auth::kMacBytes; ++i) {
    if (static_cast<std::uint8_t>(a.cmd_mac[i]) != b[b.size() - auth::kMacBytes + i]) return false;
  }
  return true;
}

}  // namespace evade::guidance_lcm::test
