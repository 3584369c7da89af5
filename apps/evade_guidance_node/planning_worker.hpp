// The guidance node's planning worker (docs/AUTONOMY.md AUT-8): a thread beside the cycle that
// runs the onboard conjunction response's assessments (GuidanceNode::plan_once) whenever the
// cycle has handed one out, and otherwise sleeps 2 ms. It is started before the loop thread
// takes SCHED_FIFO (--realtime), so it stays on the default scheduler: below the cycle, which
// it never waits on and which never waits on it. Stopped and joined when it goes out of scope.
#pragma once

#include <time.h>

#include <atomic>
#include <thread>

#include "evade/guidance_lcm/guidance_node.hpp"

namespace evade::node {

class PlanningWorker {
 public:
  explicit PlanningWorker(guidance_lcm::GuidanceNode& node) : node_(node), thread_([this] { run(); }) {}
  ~PlanningWorker() {
    stop_.store(true);
    thread_.join();
  }
  PlanningWorker(const PlanningWorker&) = delete;
  PlanningWorker& operator=(const PlanningWorker&) = delete;

 private:
  void run() noexcept {
    const timespec idle{0, 2'000'000};
    while (!stop_.load()) {
      if (!node_.plan_once()) (void)nanosleep(&idle, nullptr);  // EINTR: the loop re-checks
    }
  }
  guidance_lcm::GuidanceNode& node_;
  std::atomic<bool> stop_{false};
  std::thread thread_;  // last: started once the members it uses exist
};

}  // namespace evade::node
