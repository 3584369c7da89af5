// Internal (not installed): bounded inbox of raw evade_burn_plan_t messages for the guidance
// node (docs/GUIDANCE_NODE.md PLAN-IN-1). A plan (about 600 B encoded) does not fit the
// input queue's 256-byte slots, and plans are rare, so they get their own fixed inbox of
// kPlanSlots slots of kMaxPlanBytes: the receive callback copies bytes in, the cycle takes
// them out in arrival order. When full the OLDEST plan is discarded (the caller counts it as
// dropped). No allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace evade::guidance_lcm {

inline constexpr std::size_t kMaxPlanBytes = 1024;  ///< larger than any evade_burn_plan_t
inline constexpr std::size_t kPlanSlots = 4;

class PlanInbox {
 public:
  struct Slot {
    std::uint32_t size = 0;
    std::array<std::uint8_t, kMaxPlanBytes> data{};
  };

  bool empty() const noexcept { return size_ == 0; }
  /// Copies a message in (size <= kMaxPlanBytes). Returns false if the oldest had to go.
  bool push(const void* bytes, std::uint32_t size) noexcept {
    bool kept_all = true;
    if (size_ == kPlanSlots) {
      head_ = (head_ + 1) % kPlanSlots;
      --size_;
      kept_all = false;
    }
    Slot& s = slots_[(head_ + size_) % kPlanSlots];
    s.size = size;
    std::memcpy(s.data.data(), bytes, size);
    ++size_;
    return kept_all;
  }
  const Slot& front() const noexcept { return slots_[head_]; }
  void pop() noexcept {
    head_ = (head_ + 1) % kPlanSlots;
    --size_;
  }

 private:
  std::array<Slot, kPlanSlots> slots_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace evade::guidance_lcm
