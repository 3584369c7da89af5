// The checks every parameter flag shares (param_flags.hpp); the flags themselves are declared
// with their parameters' rows (with_flag in each module's parameter table).
#include "evade/config/param_flags.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace evade::config {
namespace {

constexpr RetiredFlag kSimRetired[] = {
    {"--rate-hz", "--sensor-rate-hz for the sensor rate (what `evade sim --rate-hz` set) or "
                  "--guidance-rate-hz for the guidance rate (what evade_guidance_node "
                  "--rate-hz sets)"},
};

bool ends_with(const std::string& s, const std::string& tail) {
  return s.size() >= tail.size() && s.compare(s.size() - tail.size(), tail.size(), tail) == 0;
}

std::string dashed(std::string s) {
  for (char& c : s) c = c == '_' ? '-' : c;
  return s;
}

}  // namespace

const RetiredFlag* sim_retired_flags(std::size_t* count) noexcept {
  *count = sizeof(kSimRetired) / sizeof(kSimRetired[0]);
  return kSimRetired;
}

std::string param_flag_problem(const std::string& key, const ParamSpec& spec) {
  if (spec.flag == nullptr) return key + ": no flag is declared with it (with_flag)";
  const std::string flag = spec.flag;
  const std::string aliases = spec.aliases == nullptr ? "" : spec.aliases;
  const std::string leaf = key.substr(key.rfind('.') == std::string::npos ? 0 : key.rfind('.') + 1);
  const std::size_t us = leaf.rfind('_');
  const bool dimensionless = std::string(spec.unit) == "-";
  if (flag.rfind("--", 0) != 0) return flag + ": a flag starts with --";
  if (!dimensionless && us == std::string::npos) return key + ": a key with a unit has a unit suffix";
  if (!dimensionless && !ends_with(flag, "-" + leaf.substr(us + 1))) {
    return flag + " sets " + key + " [" + spec.unit + "]: its name must end with -" +
           leaf.substr(us + 1);
  }
  if (dimensionless && flag != "--" + dashed(leaf)) {
    return flag + " sets the dimensionless " + key + ": its name must be --" + dashed(leaf);
  }
  if (("," + aliases + ",").find("," + flag + ",") != std::string::npos) {
    return flag + ": an alias repeats the flag";
  }
  return std::string();
}

double param_flag_value(const std::string& key, const ParamSpec& spec, const std::string& text) {
  double v = NAN;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !param_value_ok(spec, v)) {
    const bool none = spec.aliases == nullptr || *spec.aliases == '\0';
    const std::string also = none ? "" : std::string(", or ") + spec.aliases;
    throw std::invalid_argument(param_error(key, text, spec) + " (flag " +
                                (spec.flag == nullptr ? "" : spec.flag) + also + ")");
  }
  return v;
}

std::string param_flag_markdown(const ParamSpec& spec) {
  if (spec.flag == nullptr) return std::string();
  std::string md = std::string("`") + spec.flag + "`";
  const std::string aliases = spec.aliases == nullptr ? "" : spec.aliases;
  if (aliases.empty()) return md;
  std::string out;
  for (std::size_t b = 0; b <= aliases.size();) {
    const std::size_t e = std::min(aliases.find(',', b), aliases.size());
    out += (out.empty() ? "" : ", ") + std::string("`") + aliases.substr(b, e - b) + "`";
    b = e + 1;
  }
  return md + " (also " + out + ")";
}

}  // namespace evade::config
