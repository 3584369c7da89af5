// Internal (not installed): bounded inbox of command messages for the guidance node: burn
// plans (evade_burn_plan_t), arm/disarm (evade_arm_t) and key commands (evade_key_cmd_t)
// (docs/GUIDANCE_NODE.md PLAN-IN-1, docs/SECURITY.md AUTH-4..5, ARSN-1). A plan (629 B encoded)
// does not fit the input queue's 256-byte slots, and commands are rare, so they get their own
// fixed inbox of kCommandSlots slots of kMaxCommandBytes. The receive callback copies in the
// bytes of a command that passed authentication (its trailer with them); the cycle admits it
// (decode, freshness, then the ARSN commit: kAdmitted with the persist epoch it waits for),
// executes it once that epoch is on disk, and compact() removes the done ones at the end of the
// cycle (so outside the cycle no slot is kDone). When full the OLDEST command is discarded (the
// caller counts it and, when it was admitted, nothing is lost: its ARSN is behind the ground's
// retransmission). No allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "evade/auth/mac.hpp"
#include "evade/guidance_lcm/node_inputs.hpp"

namespace evade::guidance_lcm {

inline constexpr std::size_t kCommandSlots = 8;

class CommandInbox {
 public:
  enum class Stage : std::uint8_t { kReceived = 0, kAdmitted = 1, kDone = 2 };
  struct Slot {
    Input input = Input::kPlan;
    Stage stage = Stage::kReceived;
    bool authenticated = false;     ///< verified under a command key (else: policy off)
    std::int32_t key_id = 0;        ///< the trailer's (authenticated only)
    std::int64_t arsn = 0;
    auth::Mac mac{};
    std::uint64_t epoch = 0;        ///< kAdmitted: the persist epoch it waits for
    std::uint32_t size = 0;
    std::array<std::uint8_t, kMaxCommandBytes> data{};
  };

  bool empty() const noexcept { return size_ == 0; }
  bool full() const noexcept { return size_ == kCommandSlots; }
  std::size_t size() const noexcept { return size_; }
  /// Copies a message in (size <= kMaxCommandBytes) and returns its slot. When full the oldest
  /// is discarded first and *evicted (if given) is set true.
  Slot& push(Input in, const void* bytes, std::uint32_t size, bool* evicted = nullptr) noexcept {
    if (evicted != nullptr) *evicted = full();
    if (full()) pop_front();
    Slot& s = slots_[(head_ + size_) % kCommandSlots];
    s.input = in;
    s.stage = Stage::kReceived;
    s.authenticated = false;
    s.key_id = 0;
    s.arsn = 0;
    s.epoch = 0;
    s.size = size;
    std::memcpy(s.data.data(), bytes, size);
    ++size_;
    return s;
  }
  /// The i-th oldest (i < size()).
  Slot& at(std::size_t i) noexcept { return slots_[(head_ + i) % kCommandSlots]; }
  /// Removes the kDone slots, keeping the others in arrival order.
  void compact() noexcept {
    std::size_t kept = 0;
    for (std::size_t i = 0; i < size_; ++i) {
      Slot& s = at(i);
      if (s.stage == Stage::kDone) continue;
      if (kept != i) at(kept) = s;
      ++kept;
    }
    size_ = kept;
  }

 private:
  void pop_front() noexcept {
    head_ = (head_ + 1) % kCommandSlots;
    --size_;
  }

  std::array<Slot, kCommandSlots> slots_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace evade::guidance_lcm
