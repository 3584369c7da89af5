// The node's signed proposals as the ground reads them (docs/AUTONOMY.md AUT-10): the newest
// evade_cam_proposal_t of one event on EVADE_CAM_PROPOSAL that verifies under the node's
// telemetry key (the checks of the acknowledgements: docs/SECURITY.md TM-1), as JSON with the
// message's field names. Ground code: allocates, throws std::runtime_error when LCM cannot
// start.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/guidance_lcm/signed_encode.hpp"

namespace evade::lcm_link {

struct ProposalWatchResult {
  std::optional<nlohmann::json> proposal;  ///< the newest verified proposal of the event
  int verified = 0;  ///< verified proposals seen (of any event)
  int ignored = 0;   ///< proposals refused: unsigned, another key, a bad MAC, undecodable
};

/// Waits up to timeout_s for a verified proposal of event_id on channel (empty url: LCM's
/// default); the JSON holds event_id, version, proposal_id, state and reason (names and codes),
/// autonomy, pc, miss_m, burn_utime, dv_rsw_mps, dv_eci_mps, post_pc, post_miss_m,
/// veto_deadline_utime and plan_id.
ProposalWatchResult watch_proposal(const std::string& lcm_url, const std::string& channel,
                                   const guidance_lcm::SigningKey& telemetry, std::int64_t event_id,
                                   double timeout_s);

/// Records the node's verified proposals on channel from construction to destruction, on a
/// thread of its own (its own LCM instance): every one whose version, proposal, state or
/// reason differs from the last one recorded of its event, in arrival order (at most
/// kMaxChanges; the rest are counted). The ground's timeline of a run (`evade cam hil`).
class ProposalRecorder {
 public:
  static constexpr std::size_t kMaxChanges = 4096;
  struct Change {
    std::int64_t utime = 0;  ///< the proposal's utime (the node's cycle time) [us]
    nlohmann::json proposal;  ///< as watch_proposal gives it
  };
  /// Throws std::runtime_error when LCM cannot start or subscribe.
  ProposalRecorder(const std::string& lcm_url, const std::string& channel,
                   const guidance_lcm::SigningKey& telemetry);
  ~ProposalRecorder();
  ProposalRecorder(const ProposalRecorder&) = delete;
  ProposalRecorder& operator=(const ProposalRecorder&) = delete;
  std::vector<Change> changes() const;
  int verified() const;
  int ignored() const;  ///< unsigned, another key, a bad MAC, undecodable
  int dropped() const;  ///< changes beyond kMaxChanges

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace evade::lcm_link
