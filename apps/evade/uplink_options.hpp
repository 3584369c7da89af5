// The flags every signed ground command shares (`evade arm`, `evade key`): the key, the LCM
// URL, the acknowledgement timeout and the retransmission interval; and how an uplink's
// outcome is printed. No domain logic.
#pragma once

#include <cstdint>
#include <string>

#include <CLI/CLI.hpp>

#include "evade/lcm_link/command_uplink.hpp"

namespace evade::cli {

struct UplinkFlags {
  std::string key_file;
  int key_id = 0;
  std::string lcm_url;
  double ack_timeout_s = 5.0;
  double retransmit_s = 0.25;
  bool json = false;
};

/// Adds --key (required), --key-id, --lcm-url, --ack-timeout-s, --retransmit-s, --json.
void add_uplink_flags(CLI::App& app, UplinkFlags& f);
lcm_link::UplinkOptions uplink_options(const UplinkFlags& f);
/// Prints the outcome (JSON or one line) and returns its exit code (0, 3 or 4).
int report_uplink(const char* what, const lcm_link::UplinkResult& r, std::int32_t key_id, bool json);

}  // namespace evade::cli
