// `evade cam review --cdm FILE --tle FILE|--omm FILE (--proposal FILE | --event N
// --telemetry-key FILE) [--pc-red P] [--span-s S] [--threshold-m D]`: the ground's review of
// the node's proposed avoidance burn against a catalog (commands::run_cam_review; docs/
// AUTONOMY.md AUT-10): the verdict (veto or fly), why, and each close approach with and
// without the burn. The proposal comes from a saved JSON (the "proposal" this command prints)
// or from the bus, the node's newest signed evade_cam_proposal_t of the event. Exit 0 with the
// verdict, 2 bad input, 4 no verified proposal on the bus.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "evade/commands/cam_review_command.hpp"
#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/commands/screen_scenario.hpp"
#include "evade/conjunction/robust_screen.hpp"
#include "evade/guidance_lcm/channels.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "evade/lcm_link/proposal_watch.hpp"
#include "param_flag_option.hpp"

namespace {
namespace cmd_cam_review {  // a name of its own: the CLI builds as unity batches too

struct Options {
  std::string cdm, tle, omm, proposal_file, telemetry_key, lcm_url;
  double hbr_m = 0.0;
  std::int64_t event_id = 0;
  double wait_s = 5.0;
  int threads = 0;
  bool json = false;
  std::vector<evade::ParamValue> params;
};

// The proposal's JSON: the file, or the node's newest signed one of the event.
nlohmann::json proposal_json(const Options& o, int* rc) {
  if (o.proposal_file.empty() == (o.event_id == 0))
    throw std::invalid_argument("give exactly one of --proposal FILE and --event N");
  if (!o.proposal_file.empty()) {
    try {
      return nlohmann::json::parse(evade::cli::read_text_file(o.proposal_file, "--proposal"));
    } catch (const nlohmann::json::parse_error& e) {
      throw std::invalid_argument("--proposal " + o.proposal_file + ": not JSON: " + e.what());
    }
  }
  if (o.telemetry_key.empty()) throw std::invalid_argument("--event: give --telemetry-key FILE to verify the node's proposal");
  const evade::guidance_lcm::SigningKey key =
      evade::lcm_link::load_signing_key(o.telemetry_key, 0, evade::auth::KeyRole::kTelemetry);
  const evade::lcm_link::ProposalWatchResult w = evade::lcm_link::watch_proposal(
      o.lcm_url, evade::guidance_lcm::kChanCamProposal, key, o.event_id, o.wait_s);
  if (!w.proposal) {
    (void)std::fprintf(stderr, "evade cam review: no proposal of event %lld verified within %.1f s (%d of "
                       "other events verified, %d ignored)\n", static_cast<long long>(o.event_id), o.wait_s,
                       w.verified, w.ignored);
    *rc = 4;
    return nullptr;
  }
  return *w.proposal;
}

int run(const Options& o) {
  int rc = 0;
  const nlohmann::json pj = proposal_json(o, &rc);
  if (rc != 0) return rc;
  const std::string name = o.proposal_file.empty() ? "the node's proposal" : o.proposal_file;
  const evade::commands::CamReviewProposal p = evade::commands::cam_review_proposal_from_json(pj, name);
  evade::commands::CamReviewRequest req = evade::commands::read_cam_review_request(
      evade::cli::read_text_file(o.cdm, "--cdm"), o.cdm, o.hbr_m, p,
      evade::cli::read_catalog_file(o.tle, o.omm), o.tle.empty() ? o.omm : o.tle, o.params);
  req.threads = o.threads;
  const evade::commands::CamReviewResult r = evade::commands::run_cam_review(req);
  if (o.json) evade::cli::print_json(evade::commands::to_json(r));
  else (void)std::fputs(evade::commands::to_text(r).c_str(), stdout);
  return 0;
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--cdm", o->cdm, "the event's CCSDS CDM (OBJECT1: the own spacecraft)")->required();
  app.add_option("--tle", o->tle, "the catalog as TLEs");
  app.add_option("--omm", o->omm, "the catalog as OMM (KVN/XML) or GP JSON/CSV");
  app.add_option("--hbr-m", o->hbr_m, "combined hard-body radius [m] (default: from AREA_PC)")
      ->check(CLI::PositiveNumber);
  app.add_option("--proposal", o->proposal_file, "the proposal as JSON (this command's \"proposal\")");
  app.add_option("--event", o->event_id, "take the node's newest signed proposal of this event [-]")
      ->check(CLI::Range(std::int64_t{1}, INT64_MAX));
  app.add_option("--telemetry-key", o->telemetry_key, "the node's telemetry key file (with --event)");
  app.add_option("--lcm-url", o->lcm_url, "LCM URL (with --event; default: LCM_DEFAULT_URL)");
  app.add_option("--wait-s", o->wait_s, "with --event: wait this long for the proposal [s]")
      ->check(CLI::Range(0.01, 3600.0))->capture_default_str();
  (void)evade::cli::add_param_flag(app, evade::commands::conjunction_uplink_params(), "uplink.",
                                   "uplink.pc_red", &o->params);
  (void)evade::cli::add_param_flag(app, evade::commands::screen_scenario_params(), "", "span_s", &o->params);
  (void)evade::cli::add_param_flag(app, evade::conjunction::screen_options_params(), "robust.",
                                   "robust.threshold_m", &o->params);
  app.add_option("--threads", o->threads, "worker threads [-] (0: every core)")->check(CLI::Range(0, 1024));
  app.add_flag("--json", o->json, "machine-readable result");
  return [o]() { return run(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"cam", "review"}, "Screen the node's proposed avoidance burn against a catalog: veto or fly", &setup});

}  // namespace cmd_cam_review
}  // namespace
