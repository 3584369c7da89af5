// The headers every `evade` command file includes (CLI11, nlohmann/json through cli.hpp, Eigen
// and the standard library), precompiled once for the CLI's translation units (EVADE_CLI_PCH,
// apps/CMakeLists.txt): a build-time measure only. Each file still includes what it uses;
// nothing here may change how a header compiles (no macros).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <CLI/CLI.hpp>
#include <Eigen/Dense>
#include <nlohmann/json.hpp>
