// Fuzz harness: bytes received on the guidance node's input channel EVADE_NAV
// (lcm_input_harness.hpp has the properties checked and the input framing).
#include "lcm_input_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_node_input(data, size, evade::guidance_lcm::kChanNav,
                              evade::fuzz::GoodTraffic::kNavAndAngles);
  return 0;
}
