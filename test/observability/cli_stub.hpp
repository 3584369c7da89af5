// The stub registry of cli_stub.cpp.
#pragma once

#include <string>
#include <vector>

#include "cli.hpp"

namespace evade::cli {
struct StubEntry {
  std::vector<std::string> path;
  Setup setup;
};
std::vector<StubEntry>& stub_registry();
}  // namespace evade::cli
