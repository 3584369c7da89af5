// Test harness: a GuidanceNode on an in-process memq:// LCM, a scripted encounter that makes
// the law evade (so a wrongly used bad message would show as thrust or a changed command),
// and a command recorder. Everything the hot loop touches is preallocated here so the
// allocation test can use the same code.
// The rig's node holds a test command key (id 1) and a test sensor key (id 2), and its
// publisher signs what it sends like the genuine ground and sensors do (docs/SECURITY.md):
// commands with key 1, sensor messages with key 2, ARSNs from a counter. An attacker is a
// second publisher with signing off, a wrong key, or hand-made bytes.
#pragma once

#include <cstdint>
#include <cstring>
#include <memory>
#include <type_traits>
#include <vector>

#include <lcm/lcm.h>

#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/guidance/los_geometry.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/guidance_lcm/guidance_node.hpp"
#include "evade/guidance_lcm/internal/ack_outbox.hpp"
#include "evade/guidance_lcm/internal/command_inbox.hpp"
#include "evade/guidance_lcm/internal/input_queue.hpp"
#include "evade/guidance_lcm/internal/seq_tracker.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"
#include "evade/guidance_lcm/validate.hpp"

namespace evade::guidance_lcm::test {

/// A head-on-ish encounter: we sit on a 7000 km circular orbit; the object starts 10 km
/// away closing at 1 km/s with a small transverse velocity (LOS rate ~ 1e-3 rad/s).
struct Encounter {
  Vec3 r_sat0 = Vec3(7.0e6, 0.0, 0.0);
  Vec3 v_sat = Vec3(0.0, 7546.0, 0.0);
  Vec3 rel_r0 = Vec3(0.0, 10000.0, 2000.0);
  Vec3 rel_v = Vec3(0.0, -1000.0, -150.0);

  void nav_at(std::int64_t t_us, evade_nav_state_t* m) const {
    const double t = 1e-6 * static_cast<double>(t_us);
    const Vec3 r = r_sat0 + v_sat * t;
    m->utime = t_us;
    m->valid = true;
    for (int i = 0; i < 3; ++i) {
      m->r_eci_m[i] = r[i];
      m->v_eci_mps[i] = v_sat[i];
    }
  }
  void angles_at(std::int64_t t_us, evade_angles_t* m) const {
    const double t = 1e-6 * static_cast<double>(t_us);
    const Vec3 rel = rel_r0 + rel_v * t;
    const guidance::LosAngles a = guidance::los_angles_from_unit(rel.normalized());
    std::memset(m, 0, sizeof(*m));
    m->utime = t_us;
    m->valid = true;
    m->elevation_rad = a.elevation_rad;
    m->azimuth_rad = a.azimuth_rad;
    m->sigma_angle_rad = 1e-5;
  }
};

inline constexpr std::int64_t kPeriodUs = 20000;  // 50 Hz

/// The rig's keys: a command key (the ground's) and a sensor key (the simulator's).
inline SigningKey test_key(std::int32_t id, std::uint8_t fill) {
  SigningKey k;
  k.id = id;
  for (std::size_t i = 0; i < k.key.size(); ++i) k.key[i] = static_cast<std::uint8_t>(fill + i);
  return k;
}
inline SigningKey test_command_key() { return test_key(1, 0x11); }
inline SigningKey test_sensor_key() { return test_key(2, 0x5a); }
inline SigningKey test_telemetry_key() { return test_key(3, 0x33); }

/// The node's side: the three keys loaded and active, memory-only state.
inline NodeSecurity test_security() {
  NodeSecurity sec;
  const SigningKey c = test_command_key();
  const SigningKey s = test_sensor_key();
  const SigningKey t = test_telemetry_key();
  (void)sec.keys.add(c.id, auth::KeyRole::kCommand, c.key, auth::KeyState::kActive);
  (void)sec.keys.add(s.id, auth::KeyRole::kSensor, s.key, auth::KeyState::kActive);
  (void)sec.keys.add(t.id, auth::KeyRole::kTelemetry, t.key, auth::KeyState::kActive);
  return sec;
}

template <class T, class = void>
struct HasAuth : std::false_type {};
template <class T>
struct HasAuth<T, std::void_t<decltype(std::declval<T&>().auth)>> : std::true_type {};

inline bool is_command_channel(const char* channel) {
  return std::strcmp(channel, kChanPlan) == 0 || std::strcmp(channel, kChanArm) == 0 ||
         std::strcmp(channel, kChanKeyCmd) == 0 || std::strcmp(channel, kChanConjunction) == 0 ||
         std::strcmp(channel, kChanCamDecision) == 0;
}

/// Publishes on a channel (encode into a fixed buffer: no allocation). Signs every message
/// that has a security trailer (command channels with the command key, others with the sensor
/// key, ARSN +1 per message) unless signing is off.
class Publisher {
 public:
  explicit Publisher(lcm_t* lcm) : lcm_(lcm) {}
  template <typename Msg>
  void send(const char* channel, const Msg& m) {
    Msg c = m;
    int n = 0;
    if constexpr (HasAuth<Msg>::value) {
      if (signing_) {
        const SigningKey& k = is_command_channel(channel) ? command_key_ : sensor_key_;
        n = encode_signed(&c, channel, k, ++arsn_, buf_, static_cast<int>(sizeof(buf_)));
      } else {
        n = c.encode(buf_, 0, static_cast<int>(sizeof(buf_)));
      }
    } else {
      n = c.encode(buf_, 0, static_cast<int>(sizeof(buf_)));
    }
    lcm_publish(lcm_, channel, buf_, static_cast<unsigned>(n));
    ++published_;
  }
  void set_signing(bool on) { signing_ = on; }
  void set_command_key(const SigningKey& k) { command_key_ = k; }
  void set_arsn(std::int64_t next) { arsn_ = next - 1; }
  std::int64_t arsn() const { return arsn_; }
  void send_bytes(const char* channel, const void* data, unsigned size) {
    lcm_publish(lcm_, channel, data, size);
    ++published_;
  }
  std::int64_t published() const { return published_; }

 private:
  lcm_t* lcm_;
  std::uint8_t buf_[1024];
  std::int64_t published_ = 0;
  bool signing_ = true;
  std::int64_t arsn_ = 0;
  SigningKey command_key_ = test_command_key();
  SigningKey sensor_key_ = test_sensor_key();
};

/// Records every command the node publishes (subscribed on the same memq instance).
class CommandRecorder {
 public:
  CommandRecorder(lcm_t* lcm, std::size_t reserve) : lcm_(lcm) {
    cmds_.reserve(reserve);
    sub_ = lcm_subscribe(lcm, kChanCmd, &CommandRecorder::on_cmd, this);
  }
  ~CommandRecorder() { lcm_unsubscribe(lcm_, sub_); }
  const std::vector<evade_thrust_cmd_t>& commands() const { return cmds_; }
  std::int64_t decode_failures() const { return decode_failures_; }

 private:
  static void on_cmd(const lcm_recv_buf_t* rbuf, const char*, void* user) {
    auto* self = static_cast<CommandRecorder*>(user);
    evade_thrust_cmd_t m{};
    if (m.decode(rbuf->data, 0, static_cast<int>(rbuf->data_size)) < 0) {
      ++self->decode_failures_;
      return;
    }
    if (self->cmds_.size() < self->cmds_.capacity()) self->cmds_.push_back(m);
  }
  lcm_t* lcm_;
  lcm_subscription_t* sub_;
  std::vector<evade_thrust_cmd_t> cmds_;
  std::int64_t decode_failures_ = 0;
};

struct LcmDeleter {
  void operator()(lcm_t* l) const { lcm_destroy(l); }
};
using LcmPtr = std::unique_ptr<lcm_t, LcmDeleter>;

/// memq:// node + publisher + recorder.
struct Rig {
  explicit Rig(NodeConfig cfg = {}, std::size_t max_cmds = 100000,
               NodeSecurity sec = test_security())
      : lcm(lcm_create("memq://")), node(lcm.get(), cfg, nullptr, sec), pub(lcm.get()),
        rec(lcm.get(), max_cmds) {}

  /// Sends good nav + angles stamped t_us and seq, drains, runs the cycle at t_us.
  const evade_thrust_cmd_t& good_cycle(std::int64_t t_us, std::int64_t seq) {
    send_good(t_us, seq);
    return cycle(t_us);
  }
  void send_good(std::int64_t t_us, std::int64_t seq) {
    evade_nav_state_t nav{};
    enc.nav_at(t_us, &nav);
    nav.seq = seq;
    pub.send(kChanNav, nav);
    evade_angles_t a{};
    enc.angles_at(t_us, &a);
    a.seq = seq;
    pub.send(kChanAngles, a);
  }
  const evade_thrust_cmd_t& cycle(std::int64_t t_us) {
    node.drain();
    return node.run_cycle(t_us);
  }
  /// Lets the recorder see the last command (memq delivers on the next handle).
  void flush() { node.drain(); }

  Encounter enc;
  LcmPtr lcm;
  GuidanceNode node;
  Publisher pub;
  CommandRecorder rec;
};

}  // namespace evade::guidance_lcm::test
