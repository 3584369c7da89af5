// `evade conjunction --cdm FILE [--hbr-m R] [--pc-red P] [--pc-target P] [window flags]
// [--publish --key FILE [--key-id N]]`: the onboard response's event from a CCSDS CDM
// (commands::read_conjunction_uplink; docs/AUTONOMY.md AUT-1): printed, or with --publish sent
// signed as evade_conjunction_t on EVADE_CONJUNCTION and retransmitted until the node answers
// (lcm_link::uplink_conjunction, like `evade plan --publish`). Exit 0 tracked (or already
// tracked), 2 bad input, 3 refused with its reason, 4 no acknowledgement.
#include <time.h>

#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "cli.hpp"
#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "param_flag_option.hpp"
#include "uplink_options.hpp"

namespace {
namespace cmd_conjunction {  // a name of its own: the CLI builds as unity batches too

struct Options {
  std::string cdm;
  double hbr_m = 0.0;
  std::vector<evade::ParamValue> params;  // uplink.*, typed (evade/config/param_flags.hpp)
  bool publish = false;
  evade::cli::UplinkFlags up;
};

std::int64_t now_us() {
  timespec ts{};
  (void)clock_gettime(CLOCK_REALTIME, &ts);  // CLOCK_REALTIME always exists
  return static_cast<std::int64_t>(ts.tv_sec) * 1000000 + ts.tv_nsec / 1000;
}

void print_text(const evade::commands::ConjunctionUplink& u) {
  const evade::autonomy::ConjunctionEvent& e = u.event;
  (void)std::printf("conjunction %s (%s / %s): event %lld version %d, TCA %s, HBR %.3f m, "
                    "Pc red %.3g target %.3g\n",
                    u.message_id.c_str(), u.object1.c_str(), u.object2.c_str(),
                    static_cast<long long>(e.event_id), e.version, u.tca_utc.c_str(), e.hbr_m,
                    e.pc_red, e.pc_target);
}

int run(const Options& o) {
  if (!o.publish && !o.up.sign.key_file.empty())
    throw std::invalid_argument("--key applies only with --publish");
  if (o.publish && o.up.sign.key_file.empty())
    throw std::invalid_argument("--publish: give --key FILE, the command key to sign with");
  evade::config::Scenario sc = evade::config::Scenario::empty("--cdm");
  for (const evade::ParamValue& v : o.params) sc.set_value(v);
  const evade::commands::ConjunctionUplink u = evade::commands::read_conjunction_uplink(
      sc, evade::cli::read_text_file(o.cdm, "--cdm"), o.cdm, o.hbr_m, now_us());
  nlohmann::json j = {{"event", evade::commands::to_json(u)}};
  int rc = 0;
  if (o.publish) {
    evade::cli::GroundSigner signer(o.up.sign);
    const evade::lcm_link::UplinkResult r = evade::lcm_link::uplink_conjunction(
        evade::cli::uplink_options(o.up.sign, o.up.lcm_url), u.event, signer.keys(), signer.arsn());
    if (!o.up.json) print_text(u);
    if (!o.up.json) return evade::cli::report_uplink("conjunction", r, signer.keys().command.id, false);
    j["uplink"] = evade::lcm_link::to_json(r, signer.keys().command.id);
    rc = evade::lcm_link::exit_code(r);
  }
  if (o.up.json) evade::cli::print_json(j);
  else print_text(u);
  return rc;
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--cdm", o->cdm, "a CCSDS CDM file (KVN or XML); OBJECT1 is the node's spacecraft")
      ->required();
  app.add_option("--hbr-m", o->hbr_m, "combined hard-body radius [m] (default: from AREA_PC)")
      ->check(CLI::PositiveNumber);
  for (const char* key : {"pc_red", "pc_target", "window_open_before_tca_s",
                          "window_close_before_tca_s", "veto_deadline_before_tca_s", "event_id",
                          "event_version"}) {
    evade::cli::add_param_flag(app, evade::commands::conjunction_uplink_params(), "uplink.",
                               std::string("uplink.") + key, &o->params);
  }
  app.add_flag("--publish", o->publish, "send it signed to the node as evade_conjunction_t");
  evade::cli::add_signing_flags(app, o->up.sign, "with --publish: the command key file to sign with",
                                false);
  app.add_option("--lcm-url", o->up.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  app.add_flag("--json", o->up.json, "machine-readable result");
  return [o]() { return run(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"conjunction", nullptr}, "A conjunction from a CDM for the node's onboard response (--publish: signed)",
     &setup});

}  // namespace cmd_conjunction
}  // namespace
