// `evade cam hil --run burn|veto|update --lcm-url URL --key FILE --telemetry-key FILE
// [--sensor-key FILE] [hil and uplink flags] [--cdm-out DIR]`: the onboard conjunction response
// end to end (docs/AUTONOMY.md AUT-11; hil::run_conjunction_hil): the simulator lockstep against
// a node started with --lockstep, the ground's CDMs from the truth uplinked signed, the veto
// when asked; prints the run's JSON (hil::to_json). scripts/conjunction_demo runs the three.
// Exit 0 on a completed run, 2 bad input, 1 on a failure (the node silent, LCM).
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "evade/commands/conjunction_uplink_command.hpp"
#include "evade/hil/conjunction_hil.hpp"
#include "param_flag_option.hpp"
#include "uplink_options.hpp"

namespace {
namespace cmd_cam_hil {  // a name of its own: the CLI builds as unity batches too

struct Options {
  std::string run;
  std::string lcm_url;
  std::string sensor_key;
  int sensor_key_id = 0;
  double lcm_timeout_s = 10.0;
  std::string cdm_out;
  std::vector<evade::ParamValue> params;  // hil.* and uplink.*, typed
  evade::cli::SigningFlags sign;
};

void write_cdms(const evade::hil::ConjunctionHilCase& c, const std::string& dir) {
  std::filesystem::create_directories(dir);
  for (const evade::hil::HilCdm& h : c.cdms) {
    const std::string path = (std::filesystem::path(dir) / h.file_name).string();
    std::ofstream f(path);
    f << h.text;
    if (!f.good()) throw std::runtime_error("--cdm-out: cannot write " + path);
  }
}

int run(const Options& o) {
  evade::hil::HilRun which{};
  (void)evade::hil::parse_hil_run(o.run, &which);  // checked by CLI11
  const evade::hil::ConjunctionHilCase c = evade::hil::conjunction_hil_case(which, o.params);
  if (!o.cdm_out.empty()) write_cdms(c, o.cdm_out);
  evade::cli::GroundSigner signer(o.sign);
  evade::hil::HilLinkOptions link;
  link.lcm_url = o.lcm_url;
  link.sensor_key_file = o.sensor_key;
  link.sensor_key_id = o.sensor_key_id;
  link.lcm_timeout_s = o.lcm_timeout_s;
  link.uplink = evade::cli::uplink_options(o.sign, o.lcm_url);
  const evade::hil::ConjunctionHilRun r =
      evade::hil::run_conjunction_hil(c, link, signer.keys(), signer.arsn());
  evade::cli::print_json(evade::hil::to_json(c, r));
  return 0;
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--run", o->run, "burn (the node burns), veto (the ground vetoes), update (a new "
                                  "version 1 h before TCA changes the answer)")
      ->required()
      ->check(CLI::IsMember({"burn", "veto", "update"}));
  app.add_option("--lcm-url", o->lcm_url, "LCM URL of the node (started with --lockstep)")->required();
  app.add_option("--sensor-key", o->sensor_key, "sign nav and the sim clock with this sensor key file");
  app.add_option("--sensor-key-id", o->sensor_key_id, "the sensor key's id [-] (0: from the file)")
      ->check(CLI::Range(0, 2147483647));
  app.add_option("--lcm-timeout-s", o->lcm_timeout_s, "lockstep: the node's command must come within this [s]")
      ->check(CLI::Range(0.01, 600.0));
  app.add_option("--cdm-out", o->cdm_out, "write the ground's CDMs into this directory");
  for (const auto& row : evade::hil::conjunction_hil_params())
    evade::cli::add_param_flag(app, evade::hil::conjunction_hil_params(), "hil.",
                               std::string("hil.") + row.spec.key, &o->params);
  for (const char* key : {"pc_red", "pc_target", "window_open_before_tca_s", "window_close_before_tca_s",
                          "veto_deadline_before_tca_s"})
    evade::cli::add_param_flag(app, evade::commands::conjunction_uplink_params(), "uplink.",
                               std::string("uplink.") + key, &o->params);
  evade::cli::add_signing_flags(app, o->sign, "the command key file the ground signs with", true);
  return [o]() { return run(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"cam", "hil"}, "The onboard conjunction response end to end against a lockstep node", &setup});

}  // namespace cmd_cam_hil
}  // namespace
