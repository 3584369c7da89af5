// The node's anti-replay state at start (include/evade/guidance_lcm/internal/node_state.hpp).
#include "evade/guidance_lcm/internal/node_state.hpp"

#include <stdexcept>
#include <string>

namespace evade::guidance_lcm::internal {

namespace {

std::unique_ptr<auth::StateFile> open_state(const NodeSecurity& sec, auth::KeyRing* keys) {
  if (sec.state_path.empty()) {
    if (sec.init_active_key != 0) throw std::invalid_argument("--auth-init needs --auth-state FILE");
    return nullptr;
  }
  const auth::KeyEntry* tm = keys->telemetry_key();
  if (tm == nullptr) {
    throw std::invalid_argument("auth state file '" + sec.state_path + "': it is authenticated "
                                "with the node's telemetry key, and none is loaded (--keys)");
  }
  auto f = std::make_unique<auth::StateFile>(sec.state_path, *tm);
  if (sec.init_active_key == 0) {
    f->load(keys);
  } else {
    f->init(keys, sec.init_active_key, sec.init_arsn_floor);
  }
  return f;
}

}  // namespace

// A state file the node cannot start from is bad input, like a bad key file: the message names
// the file and the problem, and evade_guidance_node exits 2.
std::unique_ptr<auth::StateFile> start_auth_state(const NodeSecurity& sec, auth::KeyRing* keys) {
  try {
    return open_state(sec, keys);
  } catch (const std::runtime_error& e) {
    throw std::invalid_argument(e.what());
  }
}

}  // namespace evade::guidance_lcm::internal
