// Reading a module's parameter table (evade/core/param.hpp) from a scenario: every row at
// prefix + key, defaults from the struct passed in, ranges and error text from the table.
// Earth constants are read here and nowhere else (read_earth).
#pragma once

#include <string>

#include "evade/config/param_flags.hpp"
#include "evade/config/scenario.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/param.hpp"

namespace evade::config {

/// For each row: cfg's field = sc[prefix + key] if present (checked), else left as it is.
/// Throws ConfigError naming the key, the value and the allowed range.
template <class Cfg>
void read_params(const Scenario& sc, const std::string& prefix, const ParamTable<Cfg>& table,
                 Cfg* cfg) {
  for (const Param<Cfg>& p : table) {
    if (p.spec.type == ParamType::kSeed) {
      *p.seed(*cfg) = sc.get_seed(prefix + p.spec.key, *p.seed(*cfg));
    } else {
      p.set(*cfg, sc.get_param(prefix + p.spec.key, p.spec, p.get(*cfg)));
    }
  }
}

/// Required keys: every row whose value in `cfg` is outside its range (a struct default that
/// means "no default", such as 0 for a length) must be present at prefix + key. Call before
/// read_params. Throws ConfigError naming the key and the allowed range.
template <class Cfg>
void require_params(const Scenario& sc, const std::string& prefix, const ParamTable<Cfg>& table,
                    const Cfg& cfg) {
  for (const Param<Cfg>& p : table) {
    const std::string key = prefix + p.spec.key;
    if (!param_value_ok(p.spec, p.get(cfg)) && !sc.has(key)) {
      throw ConfigError(sc.source() + ": " + param_error(key, "<missing>", p.spec) +
                        " (required key)");
    }
  }
}

/// The declaration of the full key prefix + row key in table, or nullptr.
template <class Cfg>
const ParamSpec* find_param_spec(const ParamTable<Cfg>& table, const std::string& prefix,
                                 const std::string& full_key) {
  for (const Param<Cfg>& p : table) {
    if (prefix + p.spec.key == full_key) return &p.spec;
  }
  return nullptr;
}

/// The Earth model under "earth." (mu_m3ps2, j2, re_m), defaults from `defaults`.
EarthModel read_earth(const Scenario& sc, const EarthModel& defaults = kEarthDefault);

/// A Markdown table of a module's parameters (key with prefix, unit, default, range,
/// meaning, and the command-line flag that sets it, if any), the defaults read from a
/// default-constructed Cfg ("(required)" where that
/// default is outside the range: the key must be given).
template <class Cfg>
std::string params_markdown(const std::string& prefix, const ParamTable<Cfg>& table,
                            const Cfg& defaults = Cfg{}) {
  std::string md =
      "| key | unit | default | allowed | meaning | flag |\n|---|---|---|---|---|---|\n";
  for (const Param<Cfg>& p : table) {
    const double d = p.get(defaults);
    std::string def = param_value_text(d);
    if (p.spec.type == ParamType::kBool) def = d != 0.0 ? "true" : "false";
    if (!param_value_ok(p.spec, d)) def = "(required)";
    md.append("| `").append(prefix).append(p.spec.key).append("` | ").append(p.spec.unit);
    md.append(" | ").append(def).append(" | ").append(param_allowed_text(p.spec));
    md.append(" | ").append(p.spec.meaning).append(" | ");
    md.append(param_flag_markdown(p.spec)).append(" |\n");
  }
  return md;
}

}  // namespace evade::config
