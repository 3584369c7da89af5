// Bad data never moves the spacecraft (docs/GUIDANCE_NODE.md NODE-IN-1, NODE-IN-2, NODE-OUT-1): NaN, Inf
// and out-of-range fields, wrong types, corrupt and trailing bytes are rejected and counted, and the
// node's commands equal those of a reference node that saw only the good messages.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "fault_harness.hpp"

namespace evade::guidance_lcm::test {
namespace {

TEST(NodeFaults, RejectsNaNInfAndOutOfRangeAngles) {
  // Every 3rd cycle one bad angles message with a fresh seq, after the good one.
  std::int64_t seq = 100000;
  run_against_reference(
      150,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 3 != 0) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.seq = ++seq;  // newer seq than the good one: only validation can stop it
        switch ((k / 3) % 6) {
          case 0: a.elevation_rad = kNaN; break;
          case 1: a.azimuth_rad = kInf; break;
          case 2: a.elevation_rad = 1.6; break;  // > pi/2
          case 3: a.azimuth_rad = 7.0; break;    // > 2 pi
          case 4: a.sigma_angle_rad = -1e-3; break;
          case 5: a.has_rates = true; a.elevation_rate_radps = kNaN; a.sigma_rate_radps = 1e-4; break;
        }
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kRejected, 50);
}

TEST(NodeFaults, RejectsNaNNavState) {
  std::int64_t seq = 100000;
  run_against_reference(
      100,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 4 != 1) return 0;
        evade_nav_state_t n{};
        r.enc.nav_at(t, &n);
        n.seq = ++seq;
        if (k % 8 == 1) n.r_eci_m[1] = kNaN; else n.v_eci_mps[2] = -kInf;
        r.pub.send(kChanNav, n);
        return 1;
      },
      Verdict::kRejected, 25);
}

TEST(NodeFaults, WrongTypeAndCorruptBytesAreRejected) {
  run_against_reference(
      60,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 2 != 1) return 0;
        switch ((k / 2) % 4) {
          case 0: {  // a nav message on the angles channel: fingerprint mismatch
            evade_nav_state_t n{};
            r.enc.nav_at(t, &n);
            n.seq = 1000000 + k;
            r.pub.send(kChanAngles, n);
            break;
          }
          case 1: {  // an angles message truncated by 5 bytes
            evade_angles_t a{};
            r.enc.angles_at(t, &a);
            a.seq = 1000000 + k;
            std::uint8_t buf[512];
            const int n = a.encode(buf, 0, sizeof(buf));
            r.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n - 5));
            break;
          }
          case 2: {  // random bytes on the nav channel
            std::uint8_t buf[64];
            for (int i = 0; i < 64; ++i) buf[i] = static_cast<std::uint8_t>(37 * i + k);
            r.pub.send_bytes(kChanNav, buf, sizeof(buf));
            break;
          }
          case 3: {  // larger than any input type
            static std::uint8_t big[4096] = {};
            r.pub.send_bytes(kChanAngles, big, sizeof(big));
            break;
          }
        }
        return 1;
      },
      Verdict::kRejected, 30);
}

// NODE-IN-2: NaN or Inf in a field the flags mark unused rejects the whole message (its
// angles used to drive thrust); the commands equal those of a node that never saw it.
TEST(NodeFaults, NaNInUnusedFieldsRejectsTheWholeMessage) {
  run_against_reference(
      120,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 4 != 1) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;  // wrong data: must not be used
        a.seq = k + 2;            // newer than this cycle's good message
        a.has_rates = false;
        a.has_range = false;
        if ((k / 4) % 2 == 0) a.elevation_rate_radps = kNaN; else a.range_m = kInf;
        r.pub.send(kChanAngles, a);
        return 1;
      },
      Verdict::kRejected, 30);
}

// NODE-IN-2: a complete angles message followed by one more byte is not a message of the
// type (the decoder stops early): rejected as decode_failed, never used.
TEST(NodeFaults, MessageWithTrailingBytesIsRejected) {
  run_against_reference(
      60,
      [&](Rig& r, int k, std::int64_t t) -> std::int64_t {
        if (k % 3 != 1) return 0;
        evade_angles_t a{};
        r.enc.angles_at(t, &a);
        a.elevation_rad += 0.05;  // wrong data: must not be used
        a.seq = k + 2;            // newer than this cycle's good message
        std::uint8_t buf[512] = {};
        const int n = a.encode(buf, 0, sizeof(buf));
        r.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n + 1));
        return 1;
      },
      Verdict::kRejected, 20);
  Rig rig;
  evade_angles_t a{};
  rig.enc.angles_at(1000000, &a);
  a.seq = 1;
  std::uint8_t buf[512] = {};
  const int n = a.encode(buf, 0, sizeof(buf));
  rig.pub.send_bytes(kChanAngles, buf, static_cast<unsigned>(n + 1));
  rig.cycle(1000000);
  EXPECT_EQ(rig.node.counts().by_reason[static_cast<int>(Reason::kDecodeFailed)], 1);
}

TEST(NodeFaults, OnlyBadDataNeverThrusts) {
  Rig rig;
  std::int64_t t = 1000000;
  for (int k = 0; k < 100; ++k, t += kPeriodUs) {
    evade_nav_state_t n{};
    rig.enc.nav_at(t, &n);
    n.seq = k + 1;
    rig.pub.send(kChanNav, n);
    evade_angles_t a{};
    rig.enc.angles_at(t, &a);
    a.seq = k + 1;
    a.elevation_rad = (k % 2) ? kNaN : 2.0;
    rig.pub.send(kChanAngles, a);
    EXPECT_EQ(rig.cycle(t).accel_mps2, 0.0);
  }
  EXPECT_EQ(rig.node.counts().rejected, 100);
  expect_accounted(rig.node, rig.pub.published());
}

}  // namespace
}  // namespace evade::guidance_lcm::test
