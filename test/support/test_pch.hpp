// The headers nearly every test file includes, precompiled once for all test programs
// (EVADE_TEST_PCH, test/CMakeLists.txt): a build-time measure only. Each test file still
// includes what it uses; nothing here may change how a header compiles (no macros).
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>
