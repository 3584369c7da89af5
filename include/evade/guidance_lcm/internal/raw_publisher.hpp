// Allocation-free LCM publishing: lcm::LCM::publish(channel, &msg) allocates a buffer on
// every call (LCM 1.3.1), so we encode into a buffer sized once at construction and send
// the raw bytes through the C API (docs/GUIDANCE_NODE.md NODE-RT-2). Only for fixed-size types.
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include <lcm/lcm.h>

#include "evade/guidance_lcm/signed_encode.hpp"

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

/// RawPublisher for a type with a security trailer: with a signing key set, every message is
/// signed with the next ARSN of the publisher's clock (id 0: unsigned, trailer zero).
template <typename Msg>
class SigningPublisher {
 public:
  SigningPublisher(lcm_t* lcm, std::string channel) : lcm_(lcm), channel_(std::move(channel)) {
    Msg probe{};
    buf_.resize(static_cast<std::size_t>(probe.getEncodedSize()));
  }
  void set_signing_key(const SigningKey& key) noexcept { key_ = key; }
  /// Returns 0 on success, <0 on encode or send failure.
  int publish(const Msg& msg) noexcept {
    Msg m = msg;  // fixed-size type: a copy on the stack
    const int n = key_.id != 0 ? encode_signed(&m, channel_.c_str(), key_, arsn_.next(),
                                               buf_.data(), static_cast<int>(buf_.size()))
                               : m.encode(buf_.data(), 0, static_cast<int>(buf_.size()));
    if (n < 0) return n;
    return lcm_publish(lcm_, channel_.c_str(), buf_.data(), static_cast<unsigned>(n));
  }

 private:
  lcm_t* lcm_;
  std::string channel_;
  std::vector<std::uint8_t> buf_;
  SigningKey key_{};
  ArsnClock arsn_{};
};

}  // namespace evade::guidance_lcm
