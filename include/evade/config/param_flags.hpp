// Command-line flags that set parameters: one table for every executable (`evade` and
// `evade_guidance_node`), one row per parameter key. The flag is the parameter's name with
// its unit suffix ("--max-accel-mps2" sets guidance.max_accel_mps2); an alias is an older
// spelling kept for scripts (README.md "Flags"). A flag's type, unit, range and help come
// from the key's declaration (evade/core/param.hpp), and param_flag_problem() checks that the
// flag's name ends with the key's unit suffix, so a flag cannot disagree with the scenario
// key it sets. A given value becomes the scenario override "key=value": the same path as
// `--set key=value`, checked by the same table.
#pragma once

#include <cstddef>
#include <string>

#include "evade/core/param.hpp"

namespace evade::config {

struct ParamFlagRow {
  const char* key;      ///< full scenario key, "guidance.max_accel_mps2"
  const char* flag;     ///< "--max-accel-mps2"
  const char* aliases;  ///< older spellings, comma-separated ("--accel"), or ""
};

/// A flag that no longer exists, with what to use instead (refused with that text, exit 2).
struct RetiredFlag {
  const char* flag;  ///< "--rate-hz"
  const char* use;   ///< "--guidance-rate-hz (the guidance loop) or --sensor-rate-hz ..."
};

/// Every row (the table's order: guidance, node, sim, plans, screening).
const ParamFlagRow* param_flag_rows(std::size_t* count) noexcept;
/// The row of key, or nullptr when no flag sets it.
const ParamFlagRow* find_param_flag(const std::string& key) noexcept;
/// The retired flags of `evade sim`.
const RetiredFlag* sim_retired_flags(std::size_t* count) noexcept;

/// "" when row.flag is the key's leaf name with '_' as '-' or ends with the key's unit
/// suffix ("_mps2" -> "-mps2"; no suffix needed for a dimensionless "-" key), and aliases do
/// not repeat the flag; else what is wrong.
std::string param_flag_problem(const ParamFlagRow& row, const ParamSpec& spec);

/// The value of a flag's text, checked against the key's declaration. Throws
/// std::invalid_argument with the table's text (param_error: "key 'KEY' = 'TEXT' is invalid:
/// expected <allowed>", the same as for the scenario key) followed by " (flag FLAG...)".
double param_flag_value(const ParamFlagRow& row, const ParamSpec& spec, const std::string& text);

/// The override "key=value" for v, with 17 significant digits (reads back as v).
std::string param_override_text(const std::string& key, double v);

/// "`--max-accel-mps2` (also `--accel`)" for key, or "" when no flag sets it
/// (docs/PARAMETERS.md's flag column).
std::string param_flag_markdown(const std::string& key);

}  // namespace evade::config
