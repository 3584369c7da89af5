// evade::assessment: the assessment parameter table.
#include <cstdio>

#include <evade/assessment/assess_params.hpp>

int main() {
  if (evade::assessment::assess_params().size() == 0) return 1;
  std::printf("assessment ok\n");
  return 0;
}
