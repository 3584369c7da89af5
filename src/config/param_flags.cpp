// The table of parameter flags (param_flags.hpp) and the checks every reader shares.
#include "evade/config/param_flags.hpp"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace evade::config {
namespace {

// One row per key. Aliases are the spellings before the flags carried their units; an alias
// never names another parameter (sim's old `--rate-hz`, the sensor rate, is retired instead,
// because the node's old `--rate-hz` was the guidance rate).
constexpr ParamFlagRow kRows[] = {
    {"guidance.rate_hz", "--guidance-rate-hz", "--rate-hz,--guidance-hz"},
    {"guidance.stale_limit_s", "--stale-limit-s", ""},
    {"guidance.max_accel_mps2", "--max-accel-mps2", "--accel-mps2,--accel"},
    {"node.status_divider", "--status-divider", ""},
    {"node.queue_capacity", "--queue-capacity", "--queue"},
    {"encounter.detect_before_tca_s", "--detect-s", "--detect"},
    {"sensor.rate_hz", "--sensor-rate-hz", ""},
    {"sensor.noise_rad", "--noise-rad", ""},
    {"sensor.rate_noise_radps", "--rate-noise-radps", ""},
    {"evasion.dv_mps", "--dv-mps", "--dv"},
    {"transfer.dt_s", "--dt-transfer-s", "--dt-transfer"},
    {"transfer.impulses", "--impulses", ""},
    {"span_s", "--span-s", ""},
    {"robust.threshold_m", "--threshold-m", ""},
    {"robust.step_s", "--step-s", ""},
    {"assessment.window_s", "--window-s", ""},
    {"assessment.mc_max_samples", "--mc-max-samples", ""},
};

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

const ParamFlagRow* param_flag_rows(std::size_t* count) noexcept {
  *count = sizeof(kRows) / sizeof(kRows[0]);
  return kRows;
}

const ParamFlagRow* find_param_flag(const std::string& key) noexcept {
  for (const ParamFlagRow& r : kRows) {
    if (key == r.key) return &r;
  }
  return nullptr;
}

const RetiredFlag* sim_retired_flags(std::size_t* count) noexcept {
  *count = sizeof(kSimRetired) / sizeof(kSimRetired[0]);
  return kSimRetired;
}

std::string param_flag_problem(const ParamFlagRow& row, const ParamSpec& spec) {
  const std::string key = row.key, flag = row.flag;
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
  if (("," + std::string(row.aliases) + ",").find("," + flag + ",") != std::string::npos) {
    return flag + ": an alias repeats the flag";
  }
  return std::string();
}

double param_flag_value(const ParamFlagRow& row, const ParamSpec& spec, const std::string& text) {
  double v = NAN;
  std::size_t used = 0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || !param_value_ok(spec, v)) {
    const std::string also = *row.aliases == '\0' ? "" : std::string(", or ") + row.aliases;
    throw std::invalid_argument(param_error(row.key, text, spec) + " (flag " + row.flag + also +
                                ")");
  }
  return v;
}

std::string param_override_text(const std::string& key, double v) {
  std::ostringstream os;
  os << std::setprecision(17) << v;
  return key + "=" + os.str();
}

std::string param_flag_markdown(const std::string& key) {
  const ParamFlagRow* r = find_param_flag(key);
  if (r == nullptr) return std::string();
  std::string md = std::string("`") + r->flag + "`";
  std::string aliases = r->aliases;
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
