// The flags every signed ground command shares (`evade arm`, `evade key`, and the planners'
// `--publish --key`): the key, the acknowledgement timeout and the retransmission interval;
// and how an uplink's outcome is printed. No domain logic.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include "evade/lcm_link/command_uplink.hpp"

namespace evade::cli {

/// --key, --key-id, --ack-timeout-s, --retransmit-s.
struct SigningFlags {
  std::string key_file;
  int key_id = 0;
  double ack_timeout_s = 5.0;
  double retransmit_s = 0.25;
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
