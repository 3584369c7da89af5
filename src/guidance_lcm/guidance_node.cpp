// The public guidance node (include/evade/guidance_lcm/guidance_node.hpp): a thin owner of the
// internal NodeCore (internal/node_core.hpp); every call forwards.
#include "evade/guidance_lcm/guidance_node.hpp"


#include "evade/guidance_lcm/internal/node_core.hpp"

namespace evade::guidance_lcm {

GuidanceNode::GuidanceNode(lcm_t* lcm, const NodeConfig& cfg, lcm_t* out_lcm,
                           const NodeSecurity& sec)
    : core_(std::make_unique<internal::NodeCore>(lcm, cfg, out_lcm, sec)) {}
GuidanceNode::~GuidanceNode() = default;

int GuidanceNode::drain() noexcept { return core_->drain(); }
int GuidanceNode::wait_for_tick(int timeout_ms, std::int64_t* tick_utime) noexcept {
  return core_->wait_for_tick(timeout_ms, tick_utime);
}
const evade_thrust_cmd_t& GuidanceNode::run_cycle(std::int64_t now_us) noexcept {
  return core_->run_cycle(now_us);
}
int GuidanceNode::persist_auth_state() noexcept { return core_->persist_auth_state(); }
void GuidanceNode::stop() noexcept { core_->stop(); }
void GuidanceNode::record_compute_time(double us) noexcept { core_->record_compute_time(us); }
void GuidanceNode::record_wakeup_latency(double us) noexcept { core_->record_wakeup_latency(us); }
void GuidanceNode::record_overrun() noexcept { core_->record_overrun(); }

const InputCounts& GuidanceNode::counts() const noexcept { return core_->counts(); }
std::int64_t GuidanceNode::received(Input in) const noexcept { return core_->received(in); }
const CycleStats& GuidanceNode::compute_stats() const noexcept { return core_->compute_stats(); }
const CycleStats& GuidanceNode::wakeup_stats() const noexcept { return core_->wakeup_stats(); }
const guidance::GuidanceLaw& GuidanceNode::law() const noexcept { return core_->law(); }
const NodeConfig& GuidanceNode::config() const noexcept { return core_->config(); }
const evade_thrust_cmd_t& GuidanceNode::last_command() const noexcept {
  return core_->last_command();
}
const evade_guidance_status_t& GuidanceNode::last_status() const noexcept {
  return core_->last_status();
}
const evade_cmd_ack_t& GuidanceNode::last_ack() const noexcept { return core_->last_ack(); }
std::int64_t GuidanceNode::cycles() const noexcept { return core_->cycles(); }
std::int64_t GuidanceNode::publish_failures() const noexcept { return core_->publish_failures(); }
std::int64_t GuidanceNode::watchdog_cycles() const noexcept {
  return core_->law().status().watchdog_cycles;
}
std::int64_t GuidanceNode::ticks_received() const noexcept { return core_->ticks_received(); }
std::int64_t GuidanceNode::ticks_missed() const noexcept { return core_->ticks_missed(); }
bool GuidanceNode::armed() const noexcept { return core_->armed(); }
const guidance::PlanExecutor& GuidanceNode::plan_executor() const noexcept {
  return core_->plan_executor();
}
const auth::KeyRing& GuidanceNode::keys() const noexcept { return core_->keys(); }
std::int64_t GuidanceNode::auth_persist_failures() const noexcept {
  return core_->auth_persist_failures();
}
std::int64_t GuidanceNode::acks_published() const noexcept { return core_->acks_published(); }
std::int64_t GuidanceNode::acks_unsent() const noexcept { return core_->acks_unsent(); }
const autonomy::Responder& GuidanceNode::responder() const noexcept { return core_->responder(); }
bool GuidanceNode::plan_once() noexcept { return core_->plan_once(); }
bool GuidanceNode::planning_busy() const noexcept { return core_->planning_busy(); }
double GuidanceNode::last_planning_us() const noexcept { return core_->last_planning_us(); }
double GuidanceNode::max_planning_us() const noexcept { return core_->max_planning_us(); }
std::int64_t GuidanceNode::proposals_published() const noexcept {
  return core_->proposals_published();
}

}  // namespace evade::guidance_lcm
