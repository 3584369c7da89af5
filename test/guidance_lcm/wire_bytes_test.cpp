// Every LCM message type encodes to the same bytes on every target (issue 42 item 4): each type
// is filled from one deterministic sequence of values (signs, fractions, extremes of every
// integer width), encoded — signed with a fixed test key where the type carries the
// security trailer — and its size and a digest of its bytes compared with the table below,
// recorded on x86-64. LCM's encoding is big-endian and byte by byte, and so must be ours on
// aarch64, armhf and big-endian s390x (scripts/cross runs this test there under qemu-user).
// The values are exact binary fractions built with integer arithmetic and ldexp (no rounding,
// no libm): a mismatch is a byte-order, width or alignment fault, never floating point.
// EVADE_PRINT_WIRE=1 prints the table (to record it after a message type changes).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <string>

#include "evade/auth/mac.hpp"
#include "evade/evade_angles_t.hpp"
#include "evade/evade_arm_t.hpp"
#include "evade/evade_burn_plan_t.hpp"
#include "evade/evade_cam_decision_t.hpp"
#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_cmd_ack_t.hpp"
#include "evade/evade_conjunction_t.hpp"
#include "evade/evade_guidance_status_t.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/evade_nav_state_t.hpp"
#include "evade/evade_sim_clock_t.hpp"
#include "evade/evade_thrust_cmd_t.hpp"
#include "evade/guidance_lcm/signed_encode.hpp"

namespace {

// A deterministic sequence (splitmix64) for every field width.
struct Gen {
  std::uint64_t s = 0x9e3779b97f4a7c15ULL;
  std::uint64_t next() {
    s += 0x9e3779b97f4a7c15ULL;
    std::uint64_t z = s;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  }
  // An exact binary fraction: a signed 40-bit integer times 2^e, e in [-60, 20].
  double d() {
    const std::uint64_t u = next();
    const auto mant = static_cast<std::int64_t>(u >> 24) - (std::int64_t{1} << 39);
    return std::ldexp(static_cast<double>(mant), static_cast<int>(u % 81) - 60);
  }
  std::int64_t i64() { return static_cast<std::int64_t>(next()); }
  std::int32_t i32() { return static_cast<std::int32_t>(static_cast<std::uint32_t>(next())); }
  std::int16_t i16() { return static_cast<std::int16_t>(static_cast<std::uint16_t>(next())); }
  std::int8_t i8() { return static_cast<std::int8_t>(static_cast<std::uint8_t>(next())); }
  bool b() { return (next() & 1U) != 0; }
  template <typename T, std::size_t N>
  void fill(T (&a)[N], T (Gen::*f)()) {
    for (T& x : a) x = (this->*f)();
  }
  template <typename T, std::size_t N, std::size_t M>
  void fill(T (&a)[N][M], T (Gen::*f)()) {
    for (auto& row : a) fill(row, f);
  }
};

evade::guidance_lcm::SigningKey test_key() {
  evade::guidance_lcm::SigningKey k;
  k.id = 0x01020304;
  for (std::size_t i = 0; i < k.key.size(); ++i) k.key[i] = static_cast<std::uint8_t>(i * 7 + 1);
  return k;
}

constexpr std::int64_t kArsn = 0x0102030405060708LL;

struct Wire {
  int size = 0;
  std::string digest;  // first 12 bytes of HMAC-SHA-256 under the test key, hex
  std::string head;    // the first 24 bytes, hex (to read a mismatch)
};

std::string hex(const std::uint8_t* p, std::size_t n) {
  static const char* d = "0123456789abcdef";
  std::string s;
  for (std::size_t i = 0; i < n; ++i) {
    s += d[p[i] >> 4];
    s += d[p[i] & 15];
  }
  return s;
}

Wire wire_of(const std::uint8_t* buf, int n) {
  Wire w;
  w.size = n;
  if (n <= 0) return w;
  const auto k = test_key();
  const auto mac = evade::auth::hmac_sha256(k.key.data(), k.key.size(), buf,
                                            static_cast<std::size_t>(n));
  w.digest = hex(mac.data(), 12);
  w.head = hex(buf, static_cast<std::size_t>(n < 24 ? n : 24));
  return w;
}

template <typename Msg>
Wire signed_wire(Msg* m, const char* channel) {
  static std::uint8_t buf[8192];
  const int n = evade::guidance_lcm::encode_signed(m, channel, test_key(), kArsn, buf,
                                                   static_cast<int>(sizeof buf));
  return wire_of(buf, n);
}

template <typename Msg>
Wire plain_wire(const Msg& m) {
  static std::uint8_t buf[8192];
  const int n = m.encode(buf, 0, static_cast<int>(sizeof buf));
  return wire_of(buf, n);
}

Wire angles() {
  Gen g;
  evade::evade_angles_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.valid = g.b();
  m.elevation_rad = g.d(); m.azimuth_rad = g.d(); m.sigma_angle_rad = g.d();
  m.has_rates = g.b(); m.elevation_rate_radps = g.d(); m.azimuth_rate_radps = g.d();
  m.sigma_rate_radps = g.d(); m.has_range = g.b(); m.range_m = g.d(); m.range_rate_mps = g.d();
  m.sigma_range_m = g.d(); m.sigma_range_rate_mps = g.d();
  return signed_wire(&m, "EVADE_ANGLES");
}

Wire arm() {
  Gen g;
  evade::evade_arm_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.armed = g.b();
  return signed_wire(&m, "EVADE_ARM");
}

Wire burn_plan() {
  Gen g;
  evade::evade_burn_plan_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.epoch_utime = g.i64(); m.frame = g.i8();
  m.n_impulses = g.i8(); g.fill(m.impulse_t_s, &Gen::d); g.fill(m.impulse_dv_rsw_mps, &Gen::d);
  g.fill(m.impulse_dv_eci_valid, &Gen::i8); g.fill(m.impulse_dv_eci_mps, &Gen::d);
  g.fill(m.impulse_dv_mps, &Gen::d); m.eps_rad = g.d(); m.theta_rad = g.d();
  m.objective = g.i8(); m.objective_value = g.d(); m.evaluations = g.i32(); m.source = g.i16();
  return signed_wire(&m, "EVADE_BURN_PLAN");
}

Wire cam_decision() {
  Gen g;
  evade::evade_cam_decision_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.decision = g.i8(); m.event_id = g.i64();
  m.proposal_id = g.i64(); m.autonomy = g.i8();
  return signed_wire(&m, "EVADE_CAM_DECISION");
}

Wire cam_proposal() {
  Gen g;
  evade::evade_cam_proposal_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.event_id = g.i64(); m.version = g.i32();
  m.proposal_id = g.i64(); m.state = g.i8(); m.reason = g.i16(); m.autonomy = g.i8();
  m.miss_m = g.d(); m.pc = g.d(); m.pc_method = g.i8(); m.usage_flags = g.i16();
  m.nav_mismatch_sigma = g.d(); m.burn_utime = g.i64(); g.fill(m.dv_rsw_mps, &Gen::d);
  g.fill(m.dv_eci_mps, &Gen::d); m.post_pc = g.d(); m.post_miss_m = g.d();
  m.other_events_max_post_pc = g.d(); m.veto_deadline_utime = g.i64(); m.plan_id = g.i64();
  return signed_wire(&m, "EVADE_CAM_PROPOSAL");
}

Wire cmd_ack() {
  Gen g;
  evade::evade_cmd_ack_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.command = g.i8(); m.cmd_key_id = g.i32();
  m.cmd_arsn = g.i64(); g.fill(m.cmd_mac, &Gen::i8); m.outcome = g.i8(); m.reason = g.i16();
  m.detail = g.i16(); m.node_arsn = g.i64(); m.plan_id = g.i64(); m.armed = g.b();
  m.key_state = g.i8();
  return signed_wire(&m, "EVADE_CMD_ACK");
}

Wire conjunction() {
  Gen g;
  evade::evade_conjunction_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.event_id = g.i64(); m.version = g.i32();
  m.tca_utime = g.i64(); g.fill(m.r1_eci_m, &Gen::d); g.fill(m.v1_eci_mps, &Gen::d);
  g.fill(m.cov1_eci, &Gen::d); g.fill(m.r2_eci_m, &Gen::d); g.fill(m.v2_eci_mps, &Gen::d);
  g.fill(m.cov2_eci, &Gen::d); m.hbr_m = g.d(); m.pc_red = g.d(); m.pc_target = g.d();
  m.burn_window_start_utime = g.i64(); m.burn_window_end_utime = g.i64();
  m.veto_deadline_utime = g.i64();
  return signed_wire(&m, "EVADE_CONJUNCTION");
}

void fill_status_counts(Gen& g, evade::evade_guidance_status_t& m) {
  m.n_received = g.i64(); m.n_consumed = g.i64(); m.n_rejected = g.i64(); m.n_stale = g.i64();
  m.n_superseded = g.i64(); m.n_dropped = g.i64(); m.n_seq_gaps = g.i64(); m.cycles = g.i64();
  m.watchdog_cycles = g.i64(); m.overruns = g.i64(); m.cycle_p50_us = g.d();
  m.cycle_p99_us = g.d(); m.cycle_max_us = g.d();
}

Wire guidance_status() {
  Gen g;
  evade::evade_guidance_status_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.mode = g.i8(); m.reason = g.i16(); m.armed = g.b();
  m.track_valid = g.b(); m.los_rate_radps = g.d(); m.los_rate_var_rad2ps2 = g.d();
  g.fill(m.e_theta_eci, &Gen::d); g.fill(m.e_theta_cov_eci, &Gen::d); m.has_range = g.b();
  m.zem_m = g.d(); m.t_go_s = g.d(); m.dv_used_mps = g.d();
  fill_status_counts(g, m);
  m.plan_id = g.i64(); m.plan_state = g.i8(); m.plan_end = g.i8(); m.plan_n_impulses = g.i8();
  m.plan_impulses_done = g.i8(); g.fill(m.plan_dv_delivered_mps, &Gen::d);
  g.fill(m.plan_burn_start_utime, &Gen::i64); g.fill(m.plan_burn_end_utime, &Gen::i64);
  m.plan_dv_total_mps = g.d(); m.plan_n_accepted = g.i64(); m.plan_last_reject = g.i8();
  g.fill(m.plan_n_rejected, &Gen::i64); m.n_auth_failed = g.i64(); m.n_replayed = g.i64();
  m.plan_ack_id = g.i64(); m.plan_ack_result = g.i8(); m.auth_required = g.i16();
  m.auth_active_command_keys = g.i8(); m.auth_last_key_id = g.i32();
  m.auth_state_persist_failures = g.i64(); m.key_cmd_last_seq = g.i64();
  m.key_cmd_last_result = g.i8(); m.auth_n_keys = g.i8(); g.fill(m.auth_key_id, &Gen::i32);
  g.fill(m.auth_key_role, &Gen::i8); g.fill(m.auth_key_state, &Gen::i8);
  g.fill(m.auth_key_arsn, &Gen::i64); m.n_acks = g.i64(); m.n_acks_unsent = g.i64();
  return signed_wire(&m, "EVADE_GUID_STATUS");
}

Wire key_cmd() {
  Gen g;
  evade::evade_key_cmd_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.op = g.i8(); m.key_id = g.i32();
  return signed_wire(&m, "EVADE_KEY_CMD");
}

Wire nav_state() {
  Gen g;
  evade::evade_nav_state_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.valid = g.b(); g.fill(m.r_eci_m, &Gen::d);
  g.fill(m.v_eci_mps, &Gen::d);
  return signed_wire(&m, "EVADE_NAV");
}

Wire sim_clock() {
  Gen g;
  evade::evade_sim_clock_t m{};
  m.utime = g.i64(); m.seq = g.i64();
  return signed_wire(&m, "EVADE_SIM_CLOCK");
}

Wire thrust_cmd() {
  Gen g;
  evade::evade_thrust_cmd_t m{};
  m.utime = g.i64(); m.seq = g.i64(); m.mode = g.i8(); g.fill(m.u_eci, &Gen::d);
  m.accel_mps2 = g.d(); m.reason = g.i16(); m.input_utime = g.i64();
  return plain_wire(m);
}

struct Golden {
  const char* type;
  Wire (*make)();
  int size;
  const char* digest;
};

// Recorded on x86-64 (GCC 12, EVADE_PRINT_WIRE=1); the sizes are LCM's: 8 bytes of
// fingerprint, the fields big-endian, the 44-byte trailer last where the type is signed.
const Golden kGolden[] = {
    {"evade_angles_t", &angles, 151, "f82202c31eb84e0815092bcb"},
    {"evade_arm_t", &arm, 69, "769234699d941d2033c0849b"},
    {"evade_burn_plan_t", &burn_plan, 629, "e1fe2acd9f2a3d57bb67b019"},
    {"evade_cam_decision_t", &cam_decision, 86, "ff204561f63f263815791804"},
    {"evade_cam_proposal_t", &cam_proposal, 215, "df4862e0e81f3c7523c38144"},
    {"evade_cmd_ack_t", &cmd_ack, 136, "7c0c953d971015f8213e2a8f"},
    {"evade_conjunction_t", &conjunction, 808, "247b615d6f185aa878a77862"},
    {"evade_guidance_status_t", &guidance_status, 809, "159920bbb5e066588c892142"},
    {"evade_key_cmd_t", &key_cmd, 73, "719329aff06c3747ac3d4481"},
    {"evade_nav_state_t", &nav_state, 117, "79609a04b231bb9d84091bfd"},
    {"evade_sim_clock_t", &sim_clock, 68, "11b32e9f1fa90c8b52c95f00"},
    {"evade_thrust_cmd_t", &thrust_cmd, 67, "bb52187afe36f701104f268b"},
};

TEST(LcmWireBytes, EveryTypeEncodesToTheRecordedBytes) {
  ASSERT_TRUE(evade::auth::crypto_ready());
  const bool print = std::getenv("EVADE_PRINT_WIRE") != nullptr;
  for (const Golden& gold : kGolden) {
    const Wire w = gold.make();
    if (print) {
      std::printf("    {\"%s\", &..., %d, \"%s\"},\n", gold.type, w.size, w.digest.c_str());
    }
    EXPECT_EQ(w.size, gold.size) << gold.type;
    EXPECT_EQ(w.digest, gold.digest) << gold.type << ": first bytes " << w.head;
  }
}

// The trailer is where the node reads it (auth/trailer.hpp): the key id and the ARSN
// big-endian in the 44 bytes before the end, whatever the target's own byte order.
TEST(LcmWireBytes, TheTrailerIsBigEndianOnEveryTarget) {
  Gen g;
  evade::evade_sim_clock_t m{};
  m.utime = g.i64();
  m.seq = g.i64();
  std::uint8_t buf[256];
  const int n = evade::guidance_lcm::encode_signed(&m, "EVADE_SIM_CLOCK", test_key(), kArsn, buf,
                                                   static_cast<int>(sizeof buf));
  ASSERT_EQ(n, 8 + 8 + 8 + 44);
  EXPECT_EQ(hex(buf + n - 44, 12), "010203040102030405060708");
  evade::auth::TrailerView t;
  ASSERT_TRUE(evade::auth::read_trailer(buf, static_cast<std::size_t>(n), &t));
  EXPECT_EQ(t.key_id, 0x01020304);
  EXPECT_EQ(t.arsn, kArsn);
  EXPECT_TRUE(evade::auth::mac_valid(test_key().key, "EVADE_SIM_CLOCK", buf,
                                     static_cast<std::size_t>(n)));
}

}  // namespace
