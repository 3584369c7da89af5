// Parameter range checks and the one error text (see include/evade/core/param.hpp).
#include "evade/core/param.hpp"

#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace evade {

bool param_value_ok(const ParamSpec& p, double v) noexcept {
  if (!std::isfinite(v)) return false;
  if (p.type == ParamType::kBool) return v == 0.0 || v == 1.0;
  if (p.type != ParamType::kReal && v != std::floor(v)) return false;
  const bool above_lo = p.lo_open ? v > p.lo : v >= p.lo;
  return above_lo && v <= p.hi;
}

std::string param_value_text(double v) {
  char buf[40];
  // %.17g of any double is at most 24 characters: the count snprintf returns is not needed.
  (void)std::snprintf(buf, sizeof buf, "%.15g", v);
  if (std::isfinite(v) && std::strtod(buf, nullptr) != v) {
    (void)std::snprintf(buf, sizeof buf, "%.17g", v);
  }
  return buf;
}

std::string param_allowed_text(const ParamSpec& p) {
  if (p.type == ParamType::kBool) return "true or false";
  const char* what = p.type == ParamType::kReal ? "a number in " : "an integer in ";
  std::string s = what;
  s += p.lo_open ? "(" : "[";
  s += param_value_text(p.lo) + ", " + param_value_text(p.hi) + "]";
  if (p.unit != nullptr && std::string(p.unit) != "-") s += std::string(" ") + p.unit;
  return s;
}

std::string param_error(const std::string& full_key, const std::string& value_text,
                        const ParamSpec& p) {
  return "key '" + full_key + "' = '" + value_text + "' is invalid: expected " +
         param_allowed_text(p);
}

}  // namespace evade
