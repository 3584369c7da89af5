// The flags every signed ground command shares (`evade arm`, `evade key`, and the planners'
// `--publish --key`): the key, the acknowledgement timeout and the retransmission interval;
// and how an uplink's outcome is printed. No domain logic.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evade/lcm_link/command_uplink.hpp"

namespace evade::cli {

/// --key, --key-id, --telemetry-key, --ack-timeout-s, --retransmit-s.
struct SigningFlags {
  std::string key_file;
  int key_id = 0;
  std::string telemetry_key_file;  ///< empty: the --key file
  double ack_timeout_s = 5.0;
  double retransmit_s = 0.25;
};

/// The ground's signing side of one command: its keys (command and telemetry, read from the
/// key files) and its ARSN counter (auth::ArsnCounter beside the command key file, locked for
/// the command's life).
class GroundSigner {
 public:
  explicit GroundSigner(const SigningFlags& f);
  ~GroundSigner();
  GroundSigner(const GroundSigner&) = delete;
  GroundSigner& operator=(const GroundSigner&) = delete;
  const lcm_link::GroundKeys& keys() const noexcept { return keys_; }
  lcm_link::ArsnSource* arsn() noexcept;

 private:
  lcm_link::GroundKeys keys_;
  class Counter;
  std::unique_ptr<Counter> counter_;
};

/// The signing flags and the uplink's own --lcm-url and --json (`evade arm`, `evade key`).
struct UplinkFlags {
  SigningFlags sign;
  std::string lcm_url;
  bool json = false;
};

/// Adds the signing flags; key_help is --key's help text; required: --key must be given.
void add_signing_flags(CLI::App& app, SigningFlags& f, const char* key_help, bool required);
/// Adds --key (required) and the other signing flags, --lcm-url and --json.
void add_uplink_flags(CLI::App& app, UplinkFlags& f);
lcm_link::UplinkOptions uplink_options(const SigningFlags& f, const std::string& lcm_url);
/// Prints the outcome (JSON or one line) and returns its exit code (0, 3 or 4).
int report_uplink(const char* what, const lcm_link::UplinkResult& r, std::int32_t key_id, bool json);

}  // namespace evade::cli
