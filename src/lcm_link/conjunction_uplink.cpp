// The onboard conjunction response's ground commands (include/evade/lcm_link/
// command_uplink.hpp; docs/AUTONOMY.md AUT-1, AUT-7): a conjunction and the ground's decision,
// signed and retransmitted until the node answers, like a plan.
#include <string>

#include "evade/autonomy/response.hpp"
#include "evade/evade_cam_decision_t.hpp"
#include "evade/evade_conjunction_t.hpp"
#include "evade/guidance_lcm/autonomy_convert.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/lcm_link/internal/uplink_session.hpp"

namespace evade::lcm_link {

UplinkResult uplink_conjunction(const UplinkOptions& o, const autonomy::ConjunctionEvent& e,
                                const GroundKeys& keys, ArsnSource* arsn) {
  UplinkSession up(o, keys, arsn);
  evade_conjunction_t m{};
  // utime: the node refuses a conjunction stamped in its future (its clock is the reference).
  guidance_lcm::to_lcm(e, uplink_utime(o), arsn->last() + 1, &m);
  return up.run(guidance_lcm::kChanConjunction, m);
}

namespace {

// The proposal a veto or an approval names, from the node's verified proposal of the event;
// false (and *r says why) when there is none to name.
bool find_proposal(UplinkSession* up, std::int64_t event_id, std::int64_t* proposal_id,
                   UplinkResult* r) {
  evade_cam_proposal_t p{};
  if (!up->wait_proposal(event_id, &p)) {
    r->outcome = AckOutcome::kTimeout;
    r->reason = "no verified proposal";
    r->note = "no proposal of event " + std::to_string(event_id) +
              " verified under the telemetry key (" + std::to_string(up->proposals_verified()) +
              " of other events): the node may not track it; give --proposal P";
    return false;
  }
  if (p.proposal_id == 0) {
    r->outcome = AckOutcome::kRejected;
    r->reason = "no_proposal";
    r->note = "event " + std::to_string(event_id) + " version " + std::to_string(p.version) +
              " has no proposal: state " +
              autonomy::response_state_name(static_cast<autonomy::ResponseState>(p.state)) +
              ", reason " +
              autonomy::response_reason_name(static_cast<autonomy::ResponseReason>(p.reason));
    return false;
  }
  *proposal_id = p.proposal_id;
  return true;
}

}  // namespace

UplinkResult uplink_cam_decision(const UplinkOptions& o, autonomy::DecisionCommand d,
                                 const GroundKeys& keys, ArsnSource* arsn) {
  UplinkSession up(o, keys, arsn);
  const bool names_proposal = d.kind == autonomy::DecisionCommand::Kind::kVeto ||
                              d.kind == autonomy::DecisionCommand::Kind::kApprove;
  if (names_proposal && d.proposal_id == 0) {
    UplinkResult r;
    if (!find_proposal(&up, d.event_id, &d.proposal_id, &r)) return r;
  }
  evade_cam_decision_t m{};
  guidance_lcm::to_lcm(d, uplink_utime(o), arsn->last() + 1, &m);
  UplinkResult r = up.run(guidance_lcm::kChanCamDecision, m);
  r.proposal_id = d.proposal_id;
  return r;
}

}  // namespace evade::lcm_link
