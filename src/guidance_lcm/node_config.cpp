// NodeConfig::validate (include/evade/guidance_lcm/node_config.hpp): the node's table, then
// the law's.
#include "evade/guidance_lcm/node_config.hpp"

#include "evade/guidance_lcm/node_params.hpp"

namespace evade::guidance_lcm {

std::string NodeConfig::validate() const {
  const std::string err = validate_params(node_params(), *this, "node.");
  return err.empty() ? guidance.validate() : err;
}

}  // namespace evade::guidance_lcm
