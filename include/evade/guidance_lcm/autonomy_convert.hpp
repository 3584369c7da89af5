// Conversions between the onboard conjunction response (evade/autonomy/) and its LCM messages
// (docs/AUTONOMY.md AUT-1, AUT-7): the uplinked evade_conjunction_t and evade_cam_decision_t
// into the responder's plain structs and back (the ground's uplink), a tracked event's record into evade_cam_proposal_t, and
// what became of each command into the acknowledgement's reason and detail. Field for field,
// bit-exact for every double; the range checks are the responder's (check_event, decide). No
// allocation, no throw.
#pragma once

#include <cstdint>

#include "evade/autonomy/responder.hpp"
#include "evade/evade_cam_decision_t.hpp"
#include "evade/evade_cam_proposal_t.hpp"
#include "evade/evade_conjunction_t.hpp"
#include "evade/guidance_lcm/input_accounting.hpp"

namespace evade::guidance_lcm {

void from_lcm(const evade_conjunction_t& m, autonomy::ConjunctionEvent* out) noexcept;
void from_lcm(const evade_cam_decision_t& m, autonomy::DecisionCommand* out) noexcept;
/// The ground's side: the messages of an event and a decision, stamped utime and seq (the auth
/// trailer is the signer's). from_lcm of them gives e and d back, bit for bit.
void to_lcm(const autonomy::ConjunctionEvent& e, std::int64_t utime, std::int64_t seq,
            evade_conjunction_t* out) noexcept;
void to_lcm(const autonomy::DecisionCommand& d, std::int64_t utime, std::int64_t seq,
            evade_cam_decision_t* out) noexcept;

/// The proposal message of a tracked event's record (the auth trailer and seq are the
/// publisher's). superseded: the notice that the record's superseded_version was replaced.
void to_lcm(const autonomy::ResponseRecord& r, autonomy::Policy policy, std::int64_t now_us,
            bool superseded, evade_cam_proposal_t* out) noexcept;

/// How the node counts and answers a command's outcome.
struct CommandOutcome {
  Verdict verdict = Verdict::kConsumed;
  Reason reason = Reason::kOk;  ///< kOk: accepted
  std::int16_t detail = 0;      ///< evade_cmd_ack_t::CONJ_* or DECIDE_*
  bool in_force = false;        ///< a retransmission of what is in force: OUTCOME_ALREADY_IN_FORCE
};
CommandOutcome conjunction_outcome(autonomy::EventResult r, autonomy::EventProblem p) noexcept;
CommandOutcome decision_outcome(autonomy::DecisionResult r) noexcept;

}  // namespace evade::guidance_lcm
