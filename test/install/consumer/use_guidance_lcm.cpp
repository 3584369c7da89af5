// evade::guidance_lcm: a plan message with no impulse is refused at the edge.
#include <cstdio>

#include <evade/guidance_lcm/burn_plan_convert.hpp>

int main() {
  const evade::evade_burn_plan_t m{};
  if (evade::guidance_lcm::burn_plan_message_reject(m) == evade::guidance::PlanReject::kNone) return 1;
  std::printf("guidance_lcm ok\n");
  return 0;
}
