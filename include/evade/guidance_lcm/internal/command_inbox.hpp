// Internal (not installed): bounded inbox of raw command messages for the guidance node:
// burn plans (evade_burn_plan_t), arm/disarm (evade_arm_t) and key commands (evade_key_cmd_t)
// (docs/GUIDANCE_NODE.md PLAN-IN-1, docs/SECURITY.md AUTH-5). A plan (about 650 B encoded)
// does not fit the input queue's 256-byte slots, and commands are rare, so they get their own
// fixed inbox of kCommandSlots slots of kMaxCommandBytes: the receive callback copies in the
// bytes of a command that passed authentication, the cycle takes them out in arrival order
// once the anti-replay state they advanced is on disk (their persist epoch). When full the
// OLDEST command is discarded (the caller counts it as dropped). No allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace evade::guidance_lcm {

inline constexpr std::size_t kMaxCommandBytes = 1024;  ///< larger than any command type
inline constexpr std::size_t kCommandSlots = 8;

class CommandInbox {
 public:
  struct Slot {
    int channel = 0;                ///< CommandChannel of the node
    std::uint64_t epoch = 0;        ///< persist epoch it waits for (0: none)
    std::uint32_t size = 0;
    std::array<std::uint8_t, kMaxCommandBytes> data{};
  };

  bool empty() const noexcept { return size_ == 0; }
  /// Copies a message in (size <= kMaxCommandBytes). Returns false if the oldest had to go.
  bool push(int channel, std::uint64_t epoch, const void* bytes, std::uint32_t size) noexcept {
    bool kept_all = true;
    if (size_ == kCommandSlots) {
      head_ = (head_ + 1) % kCommandSlots;
      --size_;
      kept_all = false;
    }
    Slot& s = slots_[(head_ + size_) % kCommandSlots];
    s.channel = channel;
    s.epoch = epoch;
    s.size = size;
    std::memcpy(s.data.data(), bytes, size);
    ++size_;
    return kept_all;
  }
  const Slot& front() const noexcept { return slots_[head_]; }
  void pop() noexcept {
    head_ = (head_ + 1) % kCommandSlots;
    --size_;
  }

 private:
  std::array<Slot, kCommandSlots> slots_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace evade::guidance_lcm
