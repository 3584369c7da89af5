// Text helpers shared by the scenario reader's files (scenario.cpp, scenario_values.cpp).
#pragma once

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

namespace evade::config::detail {

inline std::string join(const std::vector<std::string>& v, const char* sep) {
  std::string out;
  for (std::size_t i = 0; i < v.size(); ++i) out += (i ? sep : "") + v[i];
  return out;
}

// Shortest of %.15g / %.17g that reads back as the same double.
inline std::string fmt(double v) {
  char buf[32];
  // %.17g of any double is at most 24 characters: the count snprintf returns is not needed.
  (void)std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::strtod(buf, nullptr) != v) (void)std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}

}  // namespace evade::config::detail
