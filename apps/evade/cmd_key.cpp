// `evade key --activate N | --retire N --key FILE [--key-id M]`: a signed evade_key_cmd_t,
// retransmitted until the node acknowledges it (lcm_link::uplink_key_cmd; docs/SECURITY.md
// KEY-2). Exit 0 done, 3 refused (reason named), 4 no acknowledgement.
#include <cstdio>
#include <memory>
#include <string>

#include "cli.hpp"
#include "evade/evade_key_cmd_t.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "uplink_options.hpp"

namespace {
namespace cmd_key {  // a name of its own: the CLI builds as unity batches too

struct KeyOptions {
  int activate = 0;
  int retire = 0;
  evade::cli::UplinkFlags up;
};

int run_key(const KeyOptions& o) {
  if ((o.activate > 0) == (o.retire > 0)) {
    throw std::invalid_argument("give exactly one of --activate N and --retire N");
  }
  evade::cli::GroundSigner signer(o.up.sign);
  const bool act = o.activate > 0;
  const evade::lcm_link::UplinkResult r = evade::lcm_link::uplink_key_cmd(
      evade::cli::uplink_options(o.up.sign, o.up.lcm_url),
      act ? evade::evade_key_cmd_t::OP_ACTIVATE : evade::evade_key_cmd_t::OP_RETIRE,
      act ? o.activate : o.retire, signer.keys(), signer.arsn());
  return evade::cli::report_uplink(act ? "activate key" : "retire key", r, signer.keys().command.id, o.up.json);
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<KeyOptions>();
  app.add_option("--activate", o->activate, "key id whose messages the node accepts from now on [-]")
      ->check(CLI::Range(1, 2147483647));
  app.add_option("--retire", o->retire, "key id whose messages the node rejects from now on, across restarts [-]")
      ->check(CLI::Range(1, 2147483647));
  evade::cli::add_uplink_flags(app, o->up);
  return [o]() { return run_key(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"key", nullptr}, "Activate or retire a node key with a signed command (docs/SECURITY.md)", &setup});

}  // namespace cmd_key
}  // namespace
