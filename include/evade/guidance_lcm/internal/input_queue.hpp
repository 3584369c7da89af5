// Internal (not installed): bounded queue of raw sensor messages (fixed slots, no allocation
// after construction). The LCM receive callback only authenticates (when the policy requires it)
// and copies bytes in, with the trailer's key id and ARSN; the node cycle decodes, validates,
// checks freshness and only then commits the ARSN (docs/SECURITY.md ARSN-1).
// When full, the OLDEST entry is discarded and counted as dropped (docs/GUIDANCE_NODE.md
// NODE-IN-3): for guidance the newest data matter most.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include "evade/guidance_lcm/node_inputs.hpp"

namespace evade::guidance_lcm {

struct RawMessage {
  Input channel = Input::kAngles;  ///< the input it arrived on
  std::int32_t key_id = 0;      ///< authenticated: the signer (0: the policy does not require it)
  std::int64_t arsn = 0;        ///< authenticated: the trailer's ARSN, committed on admission
  std::uint32_t size = 0;       ///< bytes used in data
  std::array<std::uint8_t, kMaxInputBytes> data{};
};

class InputQueue {
 public:
  explicit InputQueue(std::size_t capacity) : slots_(capacity) {}

  std::size_t capacity() const noexcept { return slots_.size(); }
  std::size_t size() const noexcept { return size_; }
  bool empty() const noexcept { return size_ == 0; }

  /// Copies a message in. Returns false if the oldest entry had to be discarded to make
  /// room (the caller counts it as dropped; *dropped_channel, when given, receives its
  /// channel). size must be <= kMaxInputBytes.
  bool push(Input channel, std::int32_t key_id, std::int64_t arsn, const void* bytes,
            std::uint32_t size, Input* dropped_channel = nullptr) noexcept {
    bool kept_all = true;
    if (size_ == slots_.size()) {  // drop oldest
      if (dropped_channel != nullptr) *dropped_channel = slots_[head_].channel;
      head_ = (head_ + 1) % slots_.size();
      --size_;
      kept_all = false;
    }
    RawMessage& m = slots_[(head_ + size_) % slots_.size()];
    m.channel = channel;
    m.key_id = key_id;
    m.arsn = arsn;
    m.size = size;
    std::memcpy(m.data.data(), bytes, size);
    ++size_;
    return kept_all;
  }

  /// Oldest entry; only valid when !empty().
  const RawMessage& front() const noexcept { return slots_[head_]; }
  void pop() noexcept {
    head_ = (head_ + 1) % slots_.size();
    --size_;
  }

 private:
  std::vector<RawMessage> slots_;  // allocated once, in the constructor
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace evade::guidance_lcm
