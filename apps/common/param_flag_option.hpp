// Registering the parameter flags (evade/config/param_flags.hpp) on a CLI11 command, for
// both executables. The flag, its aliases, help, type name and range come from the
// parameter's row in its module's table (with_flag); a given value is checked at parse time
// (exit 2 naming the flag, the key and the allowed range) and appended to the command's
// values as a double (ParamValue): no text form between argv and the reader.
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evade/config/param_flags.hpp"
#include "evade/config/read_params.hpp"
#include "evade/core/param.hpp"

namespace evade::cli {

/// Adds the flag declared with the row of `key` in table (rows' keys below prefix) to app,
/// with its aliases not already taken on app. Each given value lands in *values (which must
/// outlive parsing). Throws std::logic_error when the key has no row, the row declares no
/// flag, or the flag disagrees with the key.
template <class Cfg>
CLI::Option* add_param_flag(CLI::App& app, const ParamTable<Cfg>& table, const std::string& prefix,
                            const std::string& key, std::vector<ParamValue>* values) {
  const ParamSpec* found = config::find_param_spec(table, prefix, key);
  if (found == nullptr) throw std::logic_error("no declaration of " + key);
  const ParamSpec spec = *found;
  const std::string problem = config::param_flag_problem(key, spec);
  if (!problem.empty()) throw std::logic_error(problem);
  std::string names = spec.flag;
  const std::string aliases = spec.aliases == nullptr ? "" : spec.aliases;
  for (std::size_t b = 0; !aliases.empty() && b <= aliases.size();) {
    const std::size_t e = std::min(aliases.find(',', b), aliases.size());
    const std::string a = aliases.substr(b, e - b);
    if (app.get_option_no_throw(a) == nullptr) names += "," + a;
    b = e + 1;
  }
  const std::string help = std::string(spec.meaning) + " = " + key + " [" + spec.unit + "]; " +
                           param_allowed_text(spec);
  CLI::Option* opt = app.add_option_function<std::string>(
      names,
      [key, spec, values](const std::string& text) {
        try {
          values->push_back(ParamValue{key, config::param_flag_value(key, spec, text)});
        } catch (const std::invalid_argument& e) {
          throw CLI::ValidationError(spec.flag, e.what());
        }
      },
      help);
  opt->type_name(spec.type == ParamType::kInt ? "INT" : "FLOAT");
  return opt;
}

/// Adds every retired flag of list to app: given, it is refused (exit 2) with what to use.
inline void add_retired_flags(CLI::App& app, const config::RetiredFlag* list, std::size_t n) {
  for (std::size_t i = 0; i < n; ++i) {
    const config::RetiredFlag r = list[i];
    app.add_option_function<std::string>(
           r.flag,
           [r](const std::string&) {
             throw CLI::ValidationError(r.flag, std::string("retired: use ") + r.use);
           },
           std::string("retired: use ") + r.use)
        ->group("");  // hidden from --help
  }
}

}  // namespace evade::cli
