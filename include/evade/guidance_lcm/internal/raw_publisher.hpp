// Allocation-free LCM publishing: lcm::LCM::publish(channel, &msg) allocates a buffer on
// every call (LCM 1.3.1), so we encode into a buffer sized once at construction and send
// the raw bytes through the C API (docs/GUIDANCE_NODE.md NODE-RT-2). Only for fixed-size types.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <lcm/lcm.h>

namespace evade::guidance_lcm {

template <typename Msg>
class RawPublisher {
 public:
  RawPublisher(lcm_t* lcm, std::string channel) : lcm_(lcm), channel_(std::move(channel)) {
    Msg probe{};
    buf_.resize(static_cast<std::size_t>(probe.getEncodedSize()));
  }
  /// Encodes msg and publishes it. Returns 0 on success, <0 on encode or send failure.
  int publish(const Msg& msg) noexcept {
    const int n = msg.encode(buf_.data(), 0, static_cast<int>(buf_.size()));
    if (n < 0) return n;
    return lcm_publish(lcm_, channel_.c_str(), buf_.data(), static_cast<unsigned>(n));
  }
  const std::string& channel() const noexcept { return channel_; }

 private:
  lcm_t* lcm_;
  std::string channel_;
  std::vector<std::uint8_t> buf_;
};

}  // namespace evade::guidance_lcm
