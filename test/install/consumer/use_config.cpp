// evade::config: a scenario from YAML text, a typed read.
#include <cstdio>

#include <evade/config/scenario.hpp>

int main() {
  const evade::config::Scenario sc = evade::config::Scenario::from_yaml_string("a:\n  b_m: 2.5\n", "inline");
  if (sc.get_double("a.b_m", 0.0, 10.0) != 2.5) return 1;
  std::printf("config ok\n");
  return 0;
}
