// Internal (not installed): the guidance node's outbox of acknowledgements (evade_cmd_ack_t,
// docs/SECURITY.md TM-2). Each acknowledgement is built when the node decides a command's
// outcome and waits here until what the command changed is on disk (its persist epoch; 0: it
// changed nothing that is persisted), then the cycle signs and publishes it with the node's
// telemetry key. The outbox holds what one cycle can produce (kAckSlots >= the inbox's
// refusals, executions and key-state acknowledgements plus the capped callback refusals);
// when it is full the new acknowledgement is not queued and the caller counts it
// (n_acks_unsent). No allocation.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "evade/evade_cmd_ack_t.hpp"

namespace evade::guidance_lcm {

inline constexpr std::size_t kAckSlots = 32;
/// Acknowledgements of commands refused in the receive callback (replayed, standby or retired
/// key: authentic, so answerable) per cycle; a replay flood gets no more than this many answers,
/// the rest are counted unsent (the signed status carries the node's ARSNs for a ground that
/// missed its answer).
inline constexpr int kCallbackAcksPerCycle = 4;

class AckOutbox {
 public:
  struct Entry {
    evade_cmd_ack_t ack{};
    std::uint64_t epoch = 0;  ///< publish once this persist epoch is on disk
  };
  /// A slot for a new acknowledgement, or nullptr when full.
  Entry* add(std::uint64_t epoch) noexcept {
    if (size_ == kAckSlots) return nullptr;
    Entry& e = slots_[(head_ + size_) % kAckSlots];
    e = Entry{};
    e.epoch = epoch;
    ++size_;
    return &e;
  }
  bool empty() const noexcept { return size_ == 0; }
  Entry& front() noexcept { return slots_[head_]; }
  /// The i-th oldest (i < size()).
  Entry& at(std::size_t i) noexcept { return slots_[(head_ + i) % kAckSlots]; }
  void pop() noexcept {
    head_ = (head_ + 1) % kAckSlots;
    --size_;
  }
  std::size_t size() const noexcept { return size_; }

 private:
  std::array<Entry, kAckSlots> slots_{};
  std::size_t head_ = 0;
  std::size_t size_ = 0;
};

}  // namespace evade::guidance_lcm
