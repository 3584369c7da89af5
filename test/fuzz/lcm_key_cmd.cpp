// Fuzz harness: bytes received on the guidance node's input channel EVADE_KEY_CMD (key
// commands, docs/SECURITY.md KEY-2; lcm_input_harness.hpp has the properties checked and the
// input framing, whose sign bit lets mutated commands past the authentication).
#include "lcm_input_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_node_input(data, size, evade::guidance_lcm::kChanKeyCmd,
                              evade::fuzz::GoodTraffic::kNavAndAngles);
  return 0;
}
