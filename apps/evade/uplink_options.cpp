// Shared flags and report of the signed ground commands (uplink_options.hpp).
#include "uplink_options.hpp"

#include <cstdio>

#include "cli.hpp"

namespace evade::cli {

void add_signing_flags(CLI::App& app, SigningFlags& f, const char* key_help, bool required) {
  CLI::Option* key = app.add_option("--key", f.key_file, key_help);
  if (required) key->required();
  app.add_option("--key-id", f.key_id, "which key of --key [-] (default: its only command key)")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--ack-timeout-s", f.ack_timeout_s,
                 "give up waiting for the node's acknowledgement after this long [s]")
      ->check(CLI::Range(0.01, 3600.0))->capture_default_str();
  app.add_option("--retransmit-s", f.retransmit_s,
                 "send again (signed afresh) after this long without an acknowledgement [s]")
      ->check(CLI::Range(0.001, 60.0))->capture_default_str();
}

void add_uplink_flags(CLI::App& app, UplinkFlags& f) {
  add_signing_flags(app, f.sign, "command key file (`evade keygen`) to sign with", true);
  app.add_option("--lcm-url", f.lcm_url, "LCM URL (default: LCM_DEFAULT_URL or LCM's default)");
  app.add_flag("--json", f.json, "machine-readable result");
}

lcm_link::UplinkOptions uplink_options(const SigningFlags& f, const std::string& lcm_url) {
  lcm_link::UplinkOptions u;
  u.lcm_url = lcm_url;
  u.timeout_s = f.ack_timeout_s;
  u.retransmit_s = f.retransmit_s;
  return u;
}

int report_uplink(const char* what, const lcm_link::UplinkResult& r, std::int32_t key_id, bool json) {
  if (json) {
    nlohmann::json j = lcm_link::to_json(r, key_id);
    j["command"] = what;
    print_json(j);
  } else {
    (void)std::printf("%s: %s (%s) after %d transmission(s)%s\n", what,
                      lcm_link::outcome_name(r.outcome), r.reason.c_str(), r.transmissions,
                      r.outcome == lcm_link::AckOutcome::kTimeout ? "" : ", acknowledged");
  }
  return lcm_link::exit_code(r);
}

}  // namespace evade::cli
