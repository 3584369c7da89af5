// Fuzz harness: bytes received on the guidance node's input channel EVADE_BURN_PLAN
// (lcm_input_harness.hpp has the properties checked and the input framing).
#include "lcm_input_harness.hpp"

// Nav only (no detection: the law does not thrust, so a plan flies), and 0.8 s of cycles
// after the last plan: the seeds' burns are centred 0.2 s to 0.8 s after their epoch.
constexpr int kBurnTailCycles = 40;

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_node_input(data, size, evade::guidance_lcm::kChanPlan,
                              evade::fuzz::GoodTraffic::kNavOnly, kBurnTailCycles);
  return 0;
}
