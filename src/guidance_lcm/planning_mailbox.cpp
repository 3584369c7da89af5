// The planning worker's hand-over (include/evade/guidance_lcm/internal/planning_mailbox.hpp).
#include "evade/guidance_lcm/internal/planning_mailbox.hpp"

#include <time.h>

namespace evade::guidance_lcm::internal {
namespace {

std::int64_t monotonic_ns() noexcept {
  timespec ts{};
  (void)clock_gettime(CLOCK_MONOTONIC, &ts);  // CLOCK_MONOTONIC always exists: cannot fail
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000000 + ts.tv_nsec;
}

}  // namespace

bool PlanningMailbox::post(const autonomy::PlanningJob& job) noexcept {
  if (state_.load(std::memory_order_acquire) != kEmpty) return false;
  job_ = job;  // the worker reads it only after the release below
  state_.store(kPosted, std::memory_order_release);
  return true;
}

bool PlanningMailbox::take_result(autonomy::PlanningJob* job, autonomy::Assessment* a) noexcept {
  if (state_.load(std::memory_order_acquire) != kDone) return false;
  *job = job_;
  *a = result_;
  state_.store(kEmpty, std::memory_order_release);
  return true;
}

bool PlanningMailbox::busy() const noexcept {
  const int s = state_.load(std::memory_order_acquire);
  return s == kPosted || s == kRunning;
}

bool PlanningMailbox::work() noexcept {
  int expected = kPosted;
  if (!state_.compare_exchange_strong(expected, kRunning, std::memory_order_acq_rel)) return false;
  const std::int64_t t0 = monotonic_ns();
  autonomy::assess_event(job_, cfg_, kEarthDefault, &ws_, &result_);
  last_work_us_ = static_cast<double>(monotonic_ns() - t0) * 1e-3;
  state_.store(kDone, std::memory_order_release);
  return true;
}

}  // namespace evade::guidance_lcm::internal
