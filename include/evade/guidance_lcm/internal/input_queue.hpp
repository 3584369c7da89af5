// Bounded queue of raw input messages (fixed slots, no allocation after construction).
// The LCM receive callback only copies bytes in; the node cycle decodes and validates.
// When full, the OLDEST entry is discarded and counted as dropped (docs/GUIDANCE_NODE.md
// NODE-IN-3): for guidance the newest data matter most.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

namespace evade::guidance_lcm {

/// Largest input message we accept, in bytes (evade_angles_t encodes to ~120 B).
inline constexpr std::size_t kMaxInputBytes = 256;

struct RawMessage {
  int channel = 0;              ///< index of the input channel it arrived on
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
  bool push(int channel, const void* bytes, std::uint32_t size,
            int* dropped_channel = nullptr) noexcept {
    bool kept_all = true;
    if (size_ == slots_.size()) {  // drop oldest
      if (dropped_channel != nullptr) *dropped_channel = slots_[head_].channel;
      head_ = (head_ + 1) % slots_.size();
      --size_;
      kept_all = false;
    }
    RawMessage& m = slots_[(head_ + size_) % slots_.size()];
    m.channel = channel;
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
