// Command-line flags that set parameters, for every executable (`evade` and
// `evade_guidance_node`). A flag is declared with its parameter's row (evade/core/param.hpp
// with_flag): the row's key, unit, range and help are the flag's, and param_flag_problem()
// checks that the flag's name ends with the key's unit suffix ("--max-accel-mps2" sets
// guidance.max_accel_mps2), so a flag cannot disagree with the scenario key it sets. An alias
// is an older spelling kept for scripts (README.md "Flags"). A given value is checked once,
// here, and travels as a double (ParamValue) to the reader (config::Scenario::set_value).
#pragma once

#include <cstddef>
#include <string>

#include "evade/core/param.hpp"

namespace evade::config {

/// A flag that no longer exists, with what to use instead (refused with that text, exit 2).
struct RetiredFlag {
  const char* flag;  ///< "--rate-hz"
  const char* use;   ///< "--guidance-rate-hz (the guidance loop) or --sensor-rate-hz ..."
};

/// The retired flags of `evade sim`.
const RetiredFlag* sim_retired_flags(std::size_t* count) noexcept;

/// "" when spec declares a flag that is the leaf of full_key with '_' as '-' or ends with the
/// key's unit suffix ("_mps2" -> "-mps2"; no suffix needed for a dimensionless "-" key), and
/// its aliases do not repeat it; else what is wrong.
std::string param_flag_problem(const std::string& full_key, const ParamSpec& spec);

/// The value of a flag's text, checked against the key's declaration. Throws
/// std::invalid_argument with the table's text (param_error: "key 'KEY' = 'TEXT' is invalid:
/// expected <allowed>", the same as for the scenario key) followed by " (flag FLAG...)".
double param_flag_value(const std::string& full_key, const ParamSpec& spec, const std::string& text);

/// "`--max-accel-mps2` (also `--accel`)" for spec, or "" when no flag sets it
/// (docs/PARAMETERS.md's flag column).
std::string param_flag_markdown(const ParamSpec& spec);

}  // namespace evade::config
