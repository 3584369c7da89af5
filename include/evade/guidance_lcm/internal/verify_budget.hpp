// Internal (not installed): the guidance node's MAC verification budget, one per input channel
// (docs/SECURITY.md AUTH-5). Each channel may spend at most its budget of verifications between
// refills; past it a message is dropped unverified and counted (verify_budget). A flood on one
// channel therefore spends only that channel's budget: no sensor flood, and no forged flood on
// another channel, can drop a genuine command. Refills: at the end of every cycle, and, while a
// lockstep node waits for its tick, every refill window of wall time (the cycle period), so no
// burst between two ticks can leave the node without the budget to verify the next tick
// (issue 40, row 7). No allocation.
#pragma once

#include <array>
#include <cstdint>

#include "evade/guidance_lcm/node_config.hpp"
#include "evade/guidance_lcm/node_inputs.hpp"

namespace evade::guidance_lcm {

class VerifyBudget {
 public:
  explicit VerifyBudget(const AuthPolicy& p) noexcept {
    for (const InputRow& row : kInputRows) full_[index(row.input)] = p.*row.verify_budget;
    refill();
  }
  /// Spends one verification on in's channel; false (nothing spent) when its budget is gone.
  bool take(Input in) noexcept {
    int& left = left_[index(in)];
    if (left <= 0) return false;
    --left;
    return true;
  }
  void refill() noexcept { left_ = full_; }
  /// Refills when window_us of wall time (CLOCK_MONOTONIC, now_us) passed since the last refill.
  void refill_after(std::int64_t now_us, std::int64_t window_us) noexcept {
    if (now_us - last_refill_us_ < window_us) return;
    refill();
    last_refill_us_ = now_us;
  }
  void mark_refilled(std::int64_t now_us) noexcept { last_refill_us_ = now_us; }
  int left(Input in) const noexcept { return left_[index(in)]; }

 private:
  static std::size_t index(Input in) noexcept { return static_cast<std::size_t>(in); }
  std::array<int, kInputCount> full_{};
  std::array<int, kInputCount> left_{};
  std::int64_t last_refill_us_ = 0;
};

}  // namespace evade::guidance_lcm
