// JSON forms shared by every result serializer (json_values.hpp).
#include "evade/config/json_values.hpp"

#include <cstddef>

namespace evade::config {

nlohmann::json impulses_json(const BurnPlan& plan) {
  nlohmann::json a = nlohmann::json::array();
  for (int i = 0; i < plan.n_impulses && i < BurnPlan::kMaxImpulses; ++i) {
    const ImpulsiveBurn& b = plan.impulses[static_cast<std::size_t>(i)];
    a.push_back({{"t_s", b.t_s},
                 {"dv_rsw_mps", vec_json(b.dv_rsw_mps)},
                 {"dv_eci_mps", b.dv_eci_valid ? vec_json(b.dv_eci_mps) : nlohmann::json(nullptr)}});
  }
  return a;
}

}  // namespace evade::config
