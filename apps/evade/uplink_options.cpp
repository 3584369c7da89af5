// Shared flags and report of the signed ground commands (uplink_options.hpp).
#include "uplink_options.hpp"

#include <cstdio>
#include <stdexcept>

#include "cli.hpp"
#include "evade/auth/arsn_counter.hpp"
#include "evade/auth/mac.hpp"

namespace evade::cli {

// The ARSN counter of the command key (auth::ArsnCounter: persisted beside the key file).
class GroundSigner::Counter final : public lcm_link::ArsnSource {
 public:
  Counter(const std::string& key_file, std::int32_t key_id) : c_(key_file), id_(key_id) {}
  std::int64_t next() override { return c_.next(id_); }
  void raise_to(std::int64_t floor) override { c_.raise_to(id_, floor); }
  std::int64_t last() const override { return c_.last(id_); }
  bool existed() const { return c_.existed(); }
  const std::string& path() const { return c_.path(); }

 private:
  auth::ArsnCounter c_;
  std::int32_t id_;
};

GroundSigner::GroundSigner(const SigningFlags& f) {
  keys_.command = lcm_link::load_command_key(f.key_file, f.key_id);
  const std::string& tm = f.telemetry_key_file.empty() ? f.key_file : f.telemetry_key_file;
  try {
    keys_.telemetry = lcm_link::load_signing_key(tm, 0, auth::KeyRole::kTelemetry);
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(std::string(e.what()) +
                                ": the node's acknowledgements are verified with its telemetry "
                                "key; give --telemetry-key FILE (`evade keygen --role telemetry`)");
  }
  try {
    counter_ = std::make_unique<Counter>(f.key_file, keys_.command.id);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());  // a refused counter file is bad input (exit 2)
  }
  if (!counter_->existed()) {
    (void)std::fprintf(stderr, "evade: no ARSN counter at %s yet (first use, or the file was "
                       "lost): it starts at 1, and the node's answer raises it above the node's "
                       "last accepted ARSN if that is higher\n", counter_->path().c_str());
  }
}

GroundSigner::~GroundSigner() {
  auth::wipe(keys_.command.key.data(), keys_.command.key.size());
  auth::wipe(keys_.telemetry.key.data(), keys_.telemetry.key.size());
}

lcm_link::ArsnSource* GroundSigner::arsn() noexcept { return counter_.get(); }

void add_signing_flags(CLI::App& app, SigningFlags& f, const char* key_help, bool required) {
  CLI::Option* key = app.add_option("--key", f.key_file, key_help);
  if (required) key->required();
  app.add_option("--key-id", f.key_id, "which key of --key [-] (default: its only command key)")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--telemetry-key", f.telemetry_key_file,
                 "the node's telemetry key file, to verify its acknowledgements (default: the "
                 "telemetry key in the --key file)");
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
    (void)std::printf("%s: %s (%s) after %d transmission(s)%s%s%s\n", what,
                      lcm_link::outcome_name(r.outcome), r.reason.c_str(), r.transmissions,
                      r.outcome == lcm_link::AckOutcome::kTimeout ? "" : ", acknowledged",
                      r.note.empty() ? "" : ": ", r.note.c_str());
  }
  return lcm_link::exit_code(r);
}

}  // namespace evade::cli
