// `evade cam decide --event N --veto|--approve [--proposal P] --key FILE` or `evade cam decide
// --autonomy off|veto|approve --key FILE`: the ground's decision on the node's onboard
// conjunction response (docs/AUTONOMY.md AUT-7), signed as evade_cam_decision_t on
// EVADE_CAM_DECISION and retransmitted until the node answers (lcm_link::uplink_cam_decision).
// A veto or approval names the node's proposal: --proposal, or the one in the node's newest
// signed evade_cam_proposal_t of the event. Exit 0 applied (or already in force), 2 bad input,
// 3 refused with its reason, 4 no acknowledgement.
#include <cstdint>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "evade/autonomy/responder.hpp"
#include "evade/autonomy/response.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "uplink_options.hpp"

namespace {
namespace cmd_cam_decide {  // a name of its own: the CLI builds as unity batches too

using evade::autonomy::DecisionCommand;

struct Options {
  std::int64_t event_id = 0;
  std::int64_t proposal_id = 0;
  bool veto = false;
  bool approve = false;
  std::string autonomy;
  evade::cli::UplinkFlags up;
};

DecisionCommand decision(const Options& o) {
  const int given = o.veto + o.approve + !o.autonomy.empty();
  if (given != 1) throw std::invalid_argument("give exactly one of --veto, --approve, --autonomy");
  DecisionCommand d;
  if (!o.autonomy.empty()) {
    if (o.event_id != 0 || o.proposal_id != 0)
      throw std::invalid_argument("--event and --proposal do not apply to --autonomy (the node's policy)");
    d.kind = DecisionCommand::Kind::kSetAutonomy;
    const std::map<std::string, evade::autonomy::Policy> policies = {
        {"off", evade::autonomy::Policy::kOff},
        {"veto", evade::autonomy::Policy::kVeto},
        {"approve", evade::autonomy::Policy::kApprove}};
    d.autonomy = static_cast<std::uint8_t>(policies.at(o.autonomy));  // checked by CLI11
    return d;
  }
  if (o.event_id <= 0) throw std::invalid_argument("--veto and --approve need --event N, the event's id");
  d.kind = o.veto ? DecisionCommand::Kind::kVeto : DecisionCommand::Kind::kApprove;
  d.event_id = o.event_id;
  d.proposal_id = o.proposal_id;
  return d;
}

int run(const Options& o) {
  const DecisionCommand d = decision(o);
  evade::cli::GroundSigner signer(o.up.sign);
  const evade::lcm_link::UplinkResult r = evade::lcm_link::uplink_cam_decision(
      evade::cli::uplink_options(o.up.sign, o.up.lcm_url), d, signer.keys(), signer.arsn());
  const char* what = o.veto ? "veto" : o.approve ? "approve" : "autonomy";
  return evade::cli::report_uplink(what, r, signer.keys().command.id, o.up.json);
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--event", o->event_id, "the event's id (evade conjunction's event_id) [-]")
      ->check(CLI::Range(std::int64_t{1}, INT64_MAX));
  app.add_option("--proposal", o->proposal_id,
                 "the node's proposal id [-] (default: from its newest signed proposal of the event)")
      ->check(CLI::Range(std::int64_t{1}, INT64_MAX));
  app.add_flag("--veto", o->veto, "do not fly the proposal");
  app.add_flag("--approve", o->approve, "fly the proposal (required under autonomy approve)");
  app.add_option("--autonomy", o->autonomy, "set the node's policy")
      ->check(CLI::IsMember({"off", "veto", "approve"}));
  evade::cli::add_uplink_flags(app, o->up);
  return [o]() { return run(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"cam", "decide"}, "Veto or approve the node's avoidance burn, or set its autonomy (signed)",
     &setup});

}  // namespace cmd_cam_decide
}  // namespace
