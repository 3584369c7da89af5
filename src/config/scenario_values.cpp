// The scenario reader's typed reads (scenario.hpp): numbers, integers, booleans, strings,
// enumerations, lists, declared parameters and seeds, each checked against what the caller
// allows, with the one error text; and the values given typed (set_value: a flag, a Python
// keyword), which reach get_param and get_double as doubles, never as text.
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdlib>

#include "evade/config/scenario.hpp"
#include "scenario_text.hpp"

namespace evade::config {

using nlohmann::json;
using detail::fmt;
using detail::join;

namespace {
bool parse_double_strict(const std::string& s, double& out) {
  if (s.empty()) return false;
  char* end = nullptr;
  out = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size();
}
}  // namespace

void Scenario::set_value(const ParamValue& v) {
  for (ParamValue& t : typed_) {
    if (t.key == v.key) {
      t.value = v.value;
      return;
    }
  }
  typed_.push_back(v);
}

const double* Scenario::typed(const std::string& key) const {
  for (const ParamValue& t : typed_) {
    if (t.key == key) return &t.value;
  }
  return nullptr;
}

double Scenario::get_double(const std::string& key, double min, double max) const {
  if (const double* t = typed(key)) {
    if (!(std::isfinite(*t) && *t >= min && *t <= max))
      fail(key, fmt(*t), "a finite number in [" + fmt(min) + ", " + fmt(max) + "]");
    record(key, *t);
    return *t;
  }
  const json* n = find(key);
  if (!n) fail(key, "<missing>", "a number in [" + fmt(min) + ", " + fmt(max) + "] (required key)");
  const std::string text = scalar_text(key, *n);
  double v = 0.0;
  if (!parse_double_strict(text, v) || !std::isfinite(v))
    fail(key, text, "a finite number in [" + fmt(min) + ", " + fmt(max) + "]");
  if (v < min || v > max) fail(key, text, "a number in [" + fmt(min) + ", " + fmt(max) + "]");
  record(key, v);
  return v;
}

double Scenario::get_double(const std::string& key, double min, double max, double fallback) const {
  if (!has(key)) {
    record(key, fallback);
    return fallback;
  }
  return get_double(key, min, max);
}

long Scenario::get_int(const std::string& key, long min, long max) const {
  const json* n = find(key);
  const std::string range = "an integer in [" + std::to_string(min) + ", " + std::to_string(max) + "]";
  if (const double* t = typed(key)) {
    if (!(*t >= static_cast<double>(min) && *t <= static_cast<double>(max) && std::trunc(*t) == *t))
      fail(key, fmt(*t), range);
    record(key, static_cast<long>(*t));
    return static_cast<long>(*t);
  }
  if (!n) fail(key, "<missing>", range + " (required key)");
  const std::string text = scalar_text(key, *n);
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(text.c_str(), &end, 10);
  if (text.empty() || end != text.c_str() + text.size() || errno == ERANGE) fail(key, text, range);
  if (v < min || v > max) fail(key, text, range);
  record(key, v);
  return v;
}

long Scenario::get_int(const std::string& key, long min, long max, long fallback) const {
  if (!has(key)) {
    record(key, fallback);
    return fallback;
  }
  return get_int(key, min, max);
}

bool Scenario::get_bool(const std::string& key) const {
  if (const double* t = typed(key)) {
    if (*t != 0.0 && *t != 1.0) fail(key, fmt(*t), "true or false");
    record(key, *t != 0.0);
    return *t != 0.0;
  }
  const json* n = find(key);
  if (!n) fail(key, "<missing>", "true or false (required key)");
  const std::string text = scalar_text(key, *n);
  if (text != "true" && text != "false") fail(key, text, "true or false");
  record(key, text == "true");
  return text == "true";
}

bool Scenario::get_bool(const std::string& key, bool fallback) const {
  if (!has(key)) {
    record(key, fallback);
    return fallback;
  }
  return get_bool(key);
}

std::string Scenario::get_string(const std::string& key) const {
  const json* n = find(key);
  if (!n) fail(key, "<missing>", "a string (required key)");
  std::string text = scalar_text(key, *n);
  record(key, text);
  return text;
}

std::string Scenario::get_string(const std::string& key, const std::string& fallback) const {
  if (!has(key)) {
    record(key, fallback);
    return fallback;
  }
  return get_string(key);
}

std::string Scenario::get_enum(const std::string& key, const std::vector<std::string>& allowed) const {
  const json* n = find(key);
  if (!n) fail(key, "<missing>", "one of {" + join(allowed, ", ") + "} (required key)");
  std::string text = scalar_text(key, *n);
  if (std::find(allowed.begin(), allowed.end(), text) == allowed.end())
    fail(key, text, "one of {" + join(allowed, ", ") + "}");
  record(key, text);
  return text;
}

std::string Scenario::get_enum(const std::string& key, const std::vector<std::string>& allowed,
                               const std::string& fallback) const {
  if (!has(key)) {
    record(key, fallback);
    return fallback;
  }
  return get_enum(key, allowed);
}

std::vector<double> Scenario::get_double_list(const std::string& key, double min, double max,
                                              std::size_t min_len) const {
  const json* n = find(key);
  const std::string what = "a list of at least " + std::to_string(min_len) +
                           " finite numbers in [" + fmt(min) + ", " + fmt(max) + "]";
  if (!n) fail(key, "<missing>", what + " (required key)");
  if (!n->is_array() || n->size() < min_len) fail(key, n->dump(), what);
  std::vector<double> out;
  for (std::size_t i = 0; i < n->size(); ++i) {
    const json& e = (*n)[i];
    double v = 0.0;
    if (!e.is_string() || !parse_double_strict(e.get<std::string>(), v) || !std::isfinite(v) ||
        v < min || v > max)
      fail(key + "." + std::to_string(i), e.is_string() ? e.get<std::string>() : e.dump(), what);
    out.push_back(v);
  }
  record(key, out);
  return out;
}

Vec3 Scenario::get_vec3(const std::string& key, double min, double max) const {
  const json* n = find(key);
  if (n && n->is_array() && n->size() != 3)
    fail(key, n->dump(), "a list of exactly 3 numbers in [" + fmt(min) + ", " + fmt(max) + "]");
  const auto v = get_double_list(key, min, max, 3);
  return Vec3(v[0], v[1], v[2]);
}

void Scenario::record_param(const std::string& key, const ParamSpec& spec, double v) const {
  if (spec.type == ParamType::kBool) {
    record(key, v != 0.0);
  } else if (spec.type == ParamType::kReal) {
    record(key, v);
  } else {
    record(key, static_cast<long long>(v));
  }
}

double Scenario::get_param(const std::string& key, const ParamSpec& spec, double fallback) const {
  if (const double* t = typed(key)) {  // given typed: the double itself
    if (!param_value_ok(spec, *t)) {
      throw ConfigError(source_ + ": " + param_error(key, param_value_text(*t), spec));
    }
    record_param(key, spec, *t);
    return *t;
  }
  const json* n = find(key);
  if (n == nullptr) {
    record(key, spec.type == ParamType::kBool ? json(fallback != 0.0) : json(fallback));
    return fallback;
  }
  const std::string text = scalar_text(key, *n);
  double v = 0.0;
  bool parsed = false;
  if (spec.type == ParamType::kBool) {
    parsed = text == "true" || text == "false";
    v = text == "true" ? 1.0 : 0.0;
  } else if (spec.type == ParamType::kReal) {
    parsed = parse_double_strict(text, v);
  } else {  // integers: decimal digits only, exact in a double up to 2^53
    char* end = nullptr;
    errno = 0;
    const long long i = std::strtoll(text.c_str(), &end, 10);
    parsed = !text.empty() && end == text.c_str() + text.size() && errno != ERANGE;
    v = static_cast<double>(i);
  }
  if (!parsed || !param_value_ok(spec, v)) {
    throw ConfigError(source_ + ": " + param_error(key, text, spec));
  }
  record_param(key, spec, v);
  return v;
}

std::uint64_t Scenario::get_seed(const std::string& key, std::uint64_t fallback) const {
  const json* n = find(key);
  if (n == nullptr) {
    record(key, fallback);
    return fallback;
  }
  const std::string text = scalar_text(key, *n);
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(text.c_str(), &end, 10);
  const bool digits = !text.empty() && std::all_of(text.begin(), text.end(), [](char c) {
    return c >= '0' && c <= '9';
  });
  if (!digits || end != text.c_str() + text.size() || errno == ERANGE) {
    fail(key, text, "an unsigned 64-bit integer seed (decimal digits)");
  }
  record(key, static_cast<std::uint64_t>(v));
  return static_cast<std::uint64_t>(v);
}


}  // namespace evade::config
