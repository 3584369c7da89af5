// Fuzz harness core for the guidance node's LCM inputs (docs/GUIDANCE_NODE.md NODE-IN-*,
// NODE-OUT-*, PLAN-IN-1): the fuzzed bytes arrive on one input channel of a real
// GuidanceNode (memq://, the same cycle code as the flight node) beside a stream of good
// traffic, exactly as if received from the network: LCM callback -> bounded queue -> decode
// -> validate -> seq/utime admission -> law -> command. A reference node receives only the
// good traffic. Checked after every cycle (abort on violation):
//   - NODE-IN-1: received == consumed + rejected + stale + superseded + dropped + auth_failed
//     + replayed, and received == the number of input messages published;
//   - NODE-OUT-2: while every fuzzed message so far was counted rejected, stale, dropped,
//     auth_failed or replayed,
//     the node's command is bit-identical to the reference's (no thrust, and no change at
//     all, from rejected data) and both consumed the same number of messages;
//   - NODE-OUT-1 and the command's own limits, always: seq +1 per cycle, utime = cycle time,
//     mode and reason in range, accel finite in [0, max_accel], |u| = 1 when thrusting,
//     zero thrust when disarmed or in SAFE.
//
// Input framing: up to kMaxRecords records, each [advance: 1 byte][size: 2 bytes LE]
// [size bytes]. The low 3 bits of `advance` are the cycles to run before the record's bytes
// are published (0: same cycle as the previous record); bit 3 set: the harness writes a valid
// MAC under the node's test command key into the record's last 32 bytes before publishing it
// (docs/SECURITY.md AUTH-1), so that mutated commands reach past the authentication into the
// decoder and the ARSN check; clear: the bytes go as they are (the authentication failure
// paths). A short last record takes what is left. Seeds are written by fuzz_make_seeds (test/fuzz/make_seeds.cpp).
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "fuzz_check.hpp"
#include "evade/auth/trailer.hpp"
#include "guidance_lcm/node_harness.hpp"

namespace evade::fuzz {

inline constexpr int kMaxRecords = 8;
inline constexpr int kWarmupCycles = 4;  // good traffic before the first record
inline constexpr int kTailCycles = 3;    // after the last record (run_node_input's default)

struct Record {
  int cycle = 0;  // delivered just before this cycle runs
  bool sign = false;
  const std::uint8_t* bytes = nullptr;
  std::uint32_t size = 0;
};

/// Splits data into records (see the file comment). Returns the number of records.
inline int parse_records(const std::uint8_t* data, std::size_t size, Record* out) {
  int n = 0;
  int cycle = kWarmupCycles;
  std::size_t pos = 0;
  while (n < kMaxRecords && pos < size) {
    cycle += data[pos] & 0x7;
    out[n].sign = (data[pos] & 0x8) != 0;
    ++pos;
    std::uint32_t len = 0;
    if (pos < size) len = data[pos];
    if (pos + 1 < size) len |= static_cast<std::uint32_t>(data[pos + 1]) << 8;
    pos += 2;
    if (pos > size) pos = size;
    if (len > size - pos) len = static_cast<std::uint32_t>(size - pos);
    out[n].cycle = cycle;
    out[n].bytes = data + pos;
    out[n].size = len;
    pos += len;
    ++n;
  }
  return n;
}

/// One memq:// LCM instance per role for the whole process (lcm_create and glib's lazily
/// grown tables would otherwise make every input look like a leak to libFuzzer's per-input
/// LeakSanitizer check, which then scans the heap each time); a fresh node per input.
inline lcm_t* process_lcm(int role) {
  static lcm_t* const lcms[2] = {lcm_create("memq://"), lcm_create("memq://")};
  return lcms[role];
}

/// A fresh GuidanceNode with the good-traffic encounter and a publisher on a process-wide
/// LCM. The destructor unsubscribes the node and handles whatever is still queued, so the
/// next input starts from an empty LCM.
struct FuzzRig {
  FuzzRig(int role, const guidance_lcm::NodeConfig& cfg)
      : lcm(process_lcm(role)), node(lcm, cfg, nullptr, guidance_lcm::test::test_security()),
        pub(lcm) {}
  ~FuzzRig() { flush(lcm); }
  static void flush(lcm_t* l) {
    for (int i = 0; i < 100000 && lcm_handle_timeout(l, 0) > 0; ++i) {
    }
  }
  void send_good(std::int64_t t_us, std::int64_t seq, bool with_angles) {
    evade_nav_state_t nav{};
    enc.nav_at(t_us, &nav);
    nav.seq = seq;
    pub.send(guidance_lcm::kChanNav, nav);
    if (!with_angles) return;
    evade_angles_t a{};
    enc.angles_at(t_us, &a);
    a.seq = seq;
    pub.send(guidance_lcm::kChanAngles, a);
  }
  const evade_thrust_cmd_t& cycle(std::int64_t t_us) {
    node.drain();
    return node.run_cycle(t_us);
  }

  guidance_lcm::test::Encounter enc;
  lcm_t* lcm;
  guidance_lcm::GuidanceNode node;
  guidance_lcm::test::Publisher pub;
};

enum class GoodTraffic { kNavAndAngles, kNavOnly };

inline bool same_command(const evade_thrust_cmd_t& a, const evade_thrust_cmd_t& b) {
  return a.utime == b.utime && a.seq == b.seq && a.mode == b.mode && a.reason == b.reason &&
         std::memcmp(&a.accel_mps2, &b.accel_mps2, sizeof(double)) == 0 &&
         std::memcmp(a.u_eci, b.u_eci, sizeof(a.u_eci)) == 0 && a.input_utime == b.input_utime;
}

/// NODE-OUT-1 and the command's limits.
inline void check_command(const evade_thrust_cmd_t& c, std::int64_t t_us, std::int64_t cycle,
                          const guidance_lcm::GuidanceNode& node) {
  EVADE_FUZZ_CHECK(c.utime == t_us, "command utime is the cycle time");
  EVADE_FUZZ_CHECK(c.seq == cycle + 1, "command seq +1 per cycle from 1");
  EVADE_FUZZ_CHECK(c.mode >= evade_thrust_cmd_t::MODE_STANDBY &&
                       c.mode <= evade_thrust_cmd_t::MODE_SAFE, "mode in range");
  EVADE_FUZZ_CHECK(c.reason >= 0 && c.reason <= evade_thrust_cmd_t::REASON_LOW_LOS_RATE,
                   "reason in range");
  EVADE_FUZZ_CHECK(std::isfinite(c.accel_mps2) && c.accel_mps2 >= 0.0 &&
                       c.accel_mps2 <= node.config().guidance.max_accel_mps2,
                   "accel finite, within [0, max_accel]");
  if (c.accel_mps2 > 0.0) {
    const double n = std::sqrt(c.u_eci[0] * c.u_eci[0] + c.u_eci[1] * c.u_eci[1] +
                               c.u_eci[2] * c.u_eci[2]);
    EVADE_FUZZ_CHECK(std::fabs(n - 1.0) <= guidance_lcm::Limits::kUnitTolerance,
                     "unit thrust direction");
    EVADE_FUZZ_CHECK(node.armed(), "no thrust while disarmed");
    EVADE_FUZZ_CHECK(c.mode != evade_thrust_cmd_t::MODE_SAFE, "no thrust in SAFE");
  }
}

inline void check_accounting(const guidance_lcm::InputCounts& c, std::int64_t published) {
  EVADE_FUZZ_CHECK(c.received == published, "every published input message is received");
  EVADE_FUZZ_CHECK(c.accounted() == c.received,
                   "received == consumed + rejected + stale + superseded + dropped + "
                   "auth_failed + replayed");
}

/// Publishes a record's bytes, with a valid MAC when the record asks for one.
inline void publish(FuzzRig& rig, const char* channel, const Record& r) {
  static std::uint8_t buf[65536];
  if (!r.sign || r.size < auth::kMinSignedBytes) {
    rig.pub.send_bytes(channel, r.bytes, r.size);
    return;
  }
  std::memcpy(buf, r.bytes, r.size);
  (void)auth::sign_encoded(guidance_lcm::test::test_command_key().key, channel, buf, r.size);
  rig.pub.send_bytes(channel, buf, r.size);  // size checked above: signing cannot fail
}

/// Runs the good traffic on a DUT and a reference node, the records on `channel` of the DUT
/// only, and checks the properties above after every cycle.
/// tail_cycles: cycles after the last record (a plan's burns come after its arrival).
inline void run_node_input(const std::uint8_t* data, std::size_t size, const char* channel,
                           GoodTraffic good, int tail_cycles = kTailCycles) {
  Record rec[kMaxRecords];
  const int n_rec = parse_records(data, size, rec);
  const int cycles = (n_rec > 0 ? rec[n_rec - 1].cycle : kWarmupCycles) + tail_cycles;
  FuzzRig dut(0, guidance_lcm::NodeConfig{});
  FuzzRig ref(1, guidance_lcm::NodeConfig{});
  bool tainted = false;  // a fuzzed message was accepted: the reference no longer applies
  int next = 0;
  for (int k = 0; k < cycles; ++k) {
    const std::int64_t t = 1000000 + k * guidance_lcm::test::kPeriodUs;
    for (FuzzRig* r : {&dut, &ref}) r->send_good(t, k + 1, good == GoodTraffic::kNavAndAngles);
    const guidance_lcm::InputCounts before = dut.node.counts();
    int m = 0;
    for (; next < n_rec && rec[next].cycle == k; ++next, ++m) publish(dut, channel, rec[next]);
    const evade_thrust_cmd_t c = dut.cycle(t);
    const evade_thrust_cmd_t r = ref.cycle(t);
    const guidance_lcm::InputCounts& after = dut.node.counts();
    check_accounting(after, dut.pub.published());
    check_accounting(ref.node.counts(), ref.pub.published());
    check_command(c, t, k, dut.node);
    const std::int64_t not_used = (after.rejected - before.rejected) +
                                  (after.stale - before.stale) + (after.dropped - before.dropped) +
                                  (after.auth_failed - before.auth_failed) +
                                  (after.replayed - before.replayed);
    if (not_used != m) tainted = true;  // some fuzzed message was accepted this cycle
    if (!tainted) {
      EVADE_FUZZ_CHECK(same_command(c, r),
                       "command equals the reference's while every fuzzed message is rejected");
      EVADE_FUZZ_CHECK(after.consumed == ref.node.counts().consumed,
                       "rejected data never counted as consumed");
    }
  }
}

}  // namespace evade::fuzz
