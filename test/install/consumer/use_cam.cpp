// evade::cam: the manoeuvre planner's parameter table.
#include <cstdio>

#include <evade/cam/cam_params.hpp>

int main() {
  if (evade::cam::cam_params().size() == 0) return 1;
  std::printf("cam ok\n");
  return 0;
}
