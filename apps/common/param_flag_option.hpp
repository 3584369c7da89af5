// Registering the parameter flags of evade/config/param_flags.hpp on a CLI11 command, for
// both executables. The option's help, type name and range come from the key's declaration;
// a given value is checked at parse time (exit 2 naming the flag, the key and the allowed
// range) and appended to the command's overrides as "key=value".
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "evade/config/param_flags.hpp"
#include "evade/core/param.hpp"

namespace evade::cli {

/// Adds the flag of `key` (declared by spec) to app, with its aliases not already taken on
/// app. Each given value lands in *overrides (which must outlive parsing). Throws
/// std::logic_error when the key has no row or the row disagrees with spec.
inline CLI::Option* add_param_flag(CLI::App& app, const std::string& key, const ParamSpec& spec,
                                   std::vector<std::string>* overrides) {
  const config::ParamFlagRow* row = config::find_param_flag(key);
  if (row == nullptr) throw std::logic_error("no flag declared for " + key);
  const std::string problem = config::param_flag_problem(*row, spec);
  if (!problem.empty()) throw std::logic_error(problem);
  std::string names = row->flag;
  const std::string aliases = row->aliases;
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
      [row, spec, overrides](const std::string& text) {
        try {
          overrides->push_back(config::param_override_text(row->key,
                                                           config::param_flag_value(*row, spec, text)));
        } catch (const std::invalid_argument& e) {
          throw CLI::ValidationError(row->flag, e.what());
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
