// Internal (not installed): the hand-over between the guidance cycle and the planning worker of
// the onboard conjunction response (docs/AUTONOMY.md AUT-8). The responder's planning job runs
// beside the cycle, never inside it: the cycle posts one job (post), the worker thread runs
// autonomy::assess_event on it (work), the cycle collects the result in a later cycle
// (take_result). One job at a time; a single atomic state orders the hand-over (the cycle
// writes the job before posting it, the worker writes the result before marking it done), so
// the cycle never waits for the worker and never takes a lock. Everything is preallocated at
// construction (the 2D Pc's quadrature workspace included): neither side allocates or throws.
// Exactly one thread may call work() (the node loop's worker, or a test in place of it).
#pragma once

#include <atomic>
#include <cstdint>

#include "evade/autonomy/response.hpp"
#include "evade/core/constants.hpp"

namespace evade::guidance_lcm::internal {

class PlanningMailbox {
 public:
  explicit PlanningMailbox(const autonomy::ResponderConfig& cfg) noexcept : cfg_(cfg) {}
  PlanningMailbox(const PlanningMailbox&) = delete;
  PlanningMailbox& operator=(const PlanningMailbox&) = delete;

  // The cycle's side.
  /// No job posted, running or waiting to be collected.
  bool idle() const noexcept { return state_.load(std::memory_order_acquire) == kEmpty; }
  /// Hands job to the worker; false (nothing posted) unless idle().
  bool post(const autonomy::PlanningJob& job) noexcept;
  /// The finished job and its assessment; false while none is done.
  bool take_result(autonomy::PlanningJob* job, autonomy::Assessment* a) noexcept;
  /// A job is posted or running (the worker has work).
  bool busy() const noexcept;

  // The worker's side.
  /// Runs the posted job, if any; true when it ran one.
  bool work() noexcept;
  /// The worker's compute time of the last job [us] (read by the cycle after take_result).
  double last_work_us() const noexcept { return last_work_us_; }

 private:
  enum State : int { kEmpty = 0, kPosted = 1, kRunning = 2, kDone = 3 };
  std::atomic<int> state_{kEmpty};
  autonomy::ResponderConfig cfg_;
  autonomy::PlanningJob job_{};
  autonomy::Assessment result_{};
  autonomy::CamWorkspace ws_{};
  double last_work_us_ = 0.0;
};

}  // namespace evade::guidance_lcm::internal
