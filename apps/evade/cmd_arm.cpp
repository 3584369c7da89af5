// `evade arm --arm|--disarm --key FILE [--key-id N]`: a signed evade_arm_t, retransmitted until
// the node's status shows the requested state (lcm_link::uplink_arm; docs/SECURITY.md
// UPLINK-*). Exit 0 acknowledged, 4 no acknowledgement.
#include <cstdio>
#include <memory>
#include <string>

#include "cli.hpp"
#include "evade/lcm_link/command_uplink.hpp"
#include "uplink_options.hpp"

namespace {
namespace cmd_arm {  // a name of its own: the CLI builds as unity batches too

struct ArmOptions {
  bool arm = false;
  bool disarm = false;
  evade::cli::UplinkFlags up;
};

int run_arm(const ArmOptions& o) {
  if (o.arm == o.disarm) throw std::invalid_argument("give exactly one of --arm and --disarm");
  evade::cli::GroundSigner signer(o.up.sign);
  const evade::lcm_link::UplinkResult r =
      evade::lcm_link::uplink_arm(evade::cli::uplink_options(o.up.sign, o.up.lcm_url), o.arm,
                                  signer.keys(), signer.arsn());
  return evade::cli::report_uplink(o.arm ? "arm" : "disarm", r, signer.keys().command.id, o.up.json);
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<ArmOptions>();
  app.add_flag("--arm", o->arm, "arm the node");
  app.add_flag("--disarm", o->disarm, "disarm the node (it commands no thrust)");
  evade::cli::add_uplink_flags(app, o->up);
  return [o]() { return run_arm(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"arm", nullptr}, "Arm or disarm the guidance node with a signed command", &setup});

}  // namespace cmd_arm
}  // namespace
