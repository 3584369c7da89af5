// `evade keygen --out FILE --key-id N [--role command|sensor|telemetry]`: a new HMAC-SHA-256 key
// from the operating system's random generator (a weak draw is drawn again), written to a new
// file with mode 0600 (auth::generate_key, auth::write_key_file; docs/SECURITY.md KEY-1). A
// telemetry key is the one the node signs its acknowledgements and status with (the ground
// holds it to verify them). Prints the file, the id and the role, never the key.
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>

#include "cli.hpp"
#include "evade/auth/key_file.hpp"

namespace {
namespace cmd_keygen {  // a name of its own: the CLI builds as unity batches too

struct KeygenOptions {
  std::string out;
  int key_id = 1;
  std::string role = "command";
  bool json = false;
};

int run_keygen(const KeygenOptions& o) {
  using namespace evade::auth;
  KeyRole role = KeyRole::kCommand;
  if (!parse_role(o.role, &role)) throw std::invalid_argument("--role " + o.role + ": not a role");
  const KeyRecord k = generate_key(o.key_id, role);  // wipes its key when it goes
  write_key_file(o.out, k);
  if (o.json) {
    evade::cli::print_json({{"key_file", o.out}, {"key_id", o.key_id}, {"role", o.role},
                            {"algorithm", "HMAC-SHA-256"}, {"mode", "0600"}});
  } else {
    (void)std::printf("wrote %s key %d (HMAC-SHA-256, 256 bits) to %s, mode 0600\n",
                      o.role.c_str(), o.key_id, o.out.c_str());
  }
  return 0;
}

evade::cli::Runner setup(CLI::App& app) {
  auto o = std::make_shared<KeygenOptions>();
  app.add_option("--out", o->out, "new key file to write (refused if it exists)")->required();
  app.add_option("--key-id", o->key_id, "key id (security association) [-]")
      ->check(CLI::Range(1, 2147483647))->capture_default_str();
  app.add_option("--role", o->role,
                 "command (plans, arm, key commands) | sensor (nav, angles, sim clock) | "
                 "telemetry (the node's acknowledgements and status)")
      ->check(CLI::IsMember({"command", "sensor", "telemetry"}))->capture_default_str();
  app.add_flag("--json", o->json, "machine-readable result");
  return [o]() { return run_keygen(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"keygen", nullptr}, "Generate a command, sensor or telemetry key file (docs/SECURITY.md)",
     &setup});

}  // namespace cmd_keygen
}  // namespace
