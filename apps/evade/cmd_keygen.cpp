// `evade keygen --out FILE --key-id N [--role command|sensor]`: a new HMAC-SHA-256 key from the
// operating system's random generator, written to a new file with mode 0600
// (auth::generate_key, auth::write_key_file; docs/SECURITY.md KEY-1). Prints the file, the id
// and the role, never the key.
#include <cstdio>
#include <memory>
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
  const KeyRole role = o.role == "sensor" ? KeyRole::kSensor : KeyRole::kCommand;
  KeyRecord k = generate_key(o.key_id, role);
  write_key_file(o.out, k);
  wipe(k.key.data(), k.key.size());
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
                 "command (plans, arm, key commands) | sensor (nav, angles, sim clock)")
      ->check(CLI::IsMember({"command", "sensor"}))->capture_default_str();
  app.add_flag("--json", o->json, "machine-readable result");
  return [o]() { return run_keygen(*o); };
}

const bool kRegistered = evade::cli::register_command(
    {{"keygen", nullptr}, "Generate a command or sensor key file (docs/SECURITY.md)", &setup});

}  // namespace cmd_keygen
}  // namespace
