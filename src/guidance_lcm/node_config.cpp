// NodeConfig::validate (include/evade/guidance_lcm/node_config.hpp): the node's table, then
// the law's.
#include "evade/guidance_lcm/node_config.hpp"

#include "evade/guidance_lcm/node_params.hpp"

namespace evade::guidance_lcm {

std::string NodeConfig::validate() const {
  std::string err = validate_params(node_params(), *this, "node.");
  if (err.empty()) err = autonomy::validate_responder_config(response);
  if (err.empty() && static_cast<int>(autonomy) > static_cast<int>(autonomy::Policy::kApprove))
    err = "node autonomy policy: not off, veto or approve";
  return err.empty() ? guidance.validate() : err;
}

}  // namespace evade::guidance_lcm
