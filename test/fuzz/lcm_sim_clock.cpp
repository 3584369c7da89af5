// Fuzz harness: bytes received on EVADE_SIM_CLOCK by a node in lockstep (NODE-LS-1), which
// runs one cycle at each accepted tick's utime, as apps/evade_guidance_node's lockstep loop
// does (drain, take the pending tick, run the cycle). Ticks are inputs like the others: each
// is in the input accounting (a tick taken is consumed). Checked: the input accounting identity
// (NODE-IN-1) after every cycle, with good nav and angles beside the ticks; a cycle runs only for a tick that decodes exactly,
// validates and is newer than the last one (never more cycles than such ticks); each
// command carries its tick's utime and seq +1; the command's limits (lcm_input_harness.hpp).
// Framing as in lcm_input_harness.hpp: `advance` counts good-traffic rounds here.
#include "evade/guidance_lcm/validate.hpp"
#include "lcm_input_harness.hpp"

namespace {

using evade::fuzz::Record;

int run(const std::uint8_t* data, std::size_t size) {
  Record rec[evade::fuzz::kMaxRecords];
  const int n_rec = evade::fuzz::parse_records(data, size, rec);
  const int rounds = (n_rec > 0 ? rec[n_rec - 1].cycle : evade::fuzz::kWarmupCycles) +
                     evade::fuzz::kTailCycles;
  evade::guidance_lcm::NodeConfig cfg;
  cfg.lockstep = true;
  evade::fuzz::FuzzRig dut(0, cfg);
  std::int64_t plausible_ticks = 0;  // decode exactly and validate (seq not checked here)
  int next = 0;
  for (int k = 0; k < rounds; ++k) {
    const std::int64_t t = 1000000 + k * evade::guidance_lcm::test::kPeriodUs;
    dut.send_good(t, k + 1, true);
    for (; next < n_rec && rec[next].cycle == k; ++next) {
      evade::evade_sim_clock_t tick{};
      const int n = tick.decode(rec[next].bytes, 0, static_cast<int>(rec[next].size));
      if (n >= 0 && n == static_cast<int>(rec[next].size) &&
          evade::guidance_lcm::validate(tick) == evade::guidance_lcm::Reason::kOk)
        ++plausible_ticks;
      // Publisher::send_bytes: a tick is an input message (published() counts it).
      dut.pub.send_bytes(evade::guidance_lcm::kChanClock, rec[next].bytes, rec[next].size);
    }
    dut.node.drain();
    std::int64_t tick_utime = 0;
    if (dut.node.wait_for_tick(0, &tick_utime) == 1) {
      const std::int64_t cycle = dut.node.cycles();
      const evade::evade_thrust_cmd_t& c = dut.node.run_cycle(tick_utime);
      evade::fuzz::check_command(c, tick_utime, cycle, dut.node);
      // Between cycles, messages wait in the queue unaccounted; after one, none does.
      evade::fuzz::check_accounting(dut.node.counts(), dut.pub.published());
    }
    EVADE_FUZZ_CHECK(dut.node.cycles() <= plausible_ticks,
                     "a cycle only for a tick that decodes and validates");
    EVADE_FUZZ_CHECK(dut.node.ticks_received() <= plausible_ticks,
                     "ticks_received counts only valid ticks");
  }
  return 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  return run(data, size);
}
