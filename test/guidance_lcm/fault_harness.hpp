// Shared by the node's fault tests (node_bad_inputs_test, node_input_order_test,
// node_watchdog_test): the accounting identity against the messages published, and a run
// against a reference node that sees only the good messages (docs/GUIDANCE_NODE.md NODE-IN-1,
// NODE-OUT-1): bad data must not change a single command.
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "node_harness.hpp"

namespace evade::guidance_lcm::test {

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
inline constexpr double kInf = std::numeric_limits<double>::infinity();

inline void expect_accounted(const GuidanceNode& node, std::int64_t published) {
  const InputCounts& c = node.counts();
  EXPECT_EQ(c.received, published);
  EXPECT_EQ(c.accounted(), published)
      << "consumed " << c.consumed << " rejected " << c.rejected << " stale " << c.stale
      << " superseded " << c.superseded << " dropped " << c.dropped;
}

inline bool same_command(const evade_thrust_cmd_t& a, const evade_thrust_cmd_t& b) {
  return a.utime == b.utime && a.seq == b.seq && a.mode == b.mode && a.reason == b.reason &&
         a.accel_mps2 == b.accel_mps2 && a.u_eci[0] == b.u_eci[0] && a.u_eci[1] == b.u_eci[1] &&
         a.u_eci[2] == b.u_eci[2] && a.input_utime == b.input_utime;
}

// A bad message injected into cycle k by `inject`; the reference rig sees only good data.
// Returns the number of bad messages published.
template <typename Inject>
void run_against_reference(int cycles, Inject inject, Verdict expected_verdict,
                           std::int64_t expected_bad) {
  Rig dut;
  Rig ref;
  std::int64_t bad = 0;
  bool evaded = false;
  for (int k = 0; k < cycles; ++k) {
    const std::int64_t t = 1000000 + k * kPeriodUs;
    dut.send_good(t, k + 1);
    bad += inject(dut, k, t);
    const evade_thrust_cmd_t c = dut.cycle(t);
    const evade_thrust_cmd_t r = ref.good_cycle(t, k + 1);
    ASSERT_TRUE(same_command(c, r)) << "cycle " << k << ": bad data changed the command";
    evaded = evaded || c.accel_mps2 > 0.0;
  }
  EXPECT_TRUE(evaded) << "the scenario must make the law thrust, or the test proves nothing";
  EXPECT_EQ(bad, expected_bad);
  expect_accounted(dut.node, dut.pub.published());
  const InputCounts& c = dut.node.counts();
  const std::int64_t bad_counted = expected_verdict == Verdict::kRejected ? c.rejected : c.stale;
  EXPECT_EQ(bad_counted, expected_bad);
}

}  // namespace evade::guidance_lcm::test
