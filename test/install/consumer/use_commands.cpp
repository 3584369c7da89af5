// evade::commands: the parameter table of `evade propagate`.
#include <cstdio>

#include <evade/commands/propagate_command.hpp>

int main() {
  if (evade::commands::propagate_params().size() == 0) return 1;
  std::printf("commands ok\n");
  return 0;
}
