// Internal (not installed): how the guidance node starts its anti-replay state (docs/SECURITY.md
// AUTH-4): from the state file, or, on a first start (--auth-init), by writing it afresh.
// Initialization only: allocates and throws std::invalid_argument naming the file and the
// problem (a state file the node cannot start from is bad input, like a bad key file).
#pragma once

#include <memory>

#include "evade/auth/keyring.hpp"
#include "evade/auth/state_file.hpp"
#include "evade/guidance_lcm/node_security.hpp"

namespace evade::guidance_lcm::internal {

/// The state file of sec applied to *keys (nullptr when sec has no state path: memory only).
std::unique_ptr<auth::StateFile> start_auth_state(const NodeSecurity& sec, auth::KeyRing* keys);

}  // namespace evade::guidance_lcm::internal
