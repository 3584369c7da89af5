// Parameter declarations: the one home of every tunable number.
//
// Each module declares its configuration struct (defaults in the member initializers) and,
// beside it, one table of Param<Cfg> rows: the key (the field's path, which carries the SI
// unit in its name), the unit, the allowed range and a one-line meaning. Every reader uses
// that table: the struct's validate(), the scenario reader (config::read_params), the guidance
// node's flags and --config, and the generated docs/PARAMETERS.md (`evade params`). A range
// or a meaning is therefore written exactly once, and every reader reports the same error
// text for the same bad value (param_error).
//
// Declare a row with EVADE_PARAM_REAL / EVADE_PARAM_INT / EVADE_PARAM_BOOL; the key is the
// field path as written (`filter.gate_chi2_2dof`), so key and field cannot drift apart.
// Reading and checking allocate (std::string): they run at initialisation, never in a cycle.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace evade {

/// kSeed: an unsigned 64-bit integer (random seeds; any value is valid). Readers move it as
/// std::uint64_t (Scenario::get_seed), never through a double.
enum class ParamType : std::uint8_t { kReal = 0, kInt = 1, kBool = 2, kSeed = 3 };

/// The declaration of one parameter, independent of the struct that holds it.
struct ParamSpec {
  const char* key;      ///< path below the module's prefix, unit suffix in the name
  const char* unit;     ///< SI unit ("m/s^2", "rad", "-" for dimensionless)
  ParamType type;
  double lo;            ///< lower limit (ignored for kBool)
  double hi;            ///< upper limit, inclusive (ignored for kBool)
  bool lo_open;         ///< true: (lo, hi]; false: [lo, hi]
  const char* meaning;  ///< one line
  /// The command-line flag that sets it ("--max-accel-mps2": the key's leaf with its unit
  /// suffix, evade/config/param_flags.hpp), or nullptr when no flag does; declared with the
  /// row (with_flag), so the flag, its help and its range cannot drift apart.
  const char* flag;
  const char* aliases;  ///< older spellings of the flag, comma-separated ("--accel"), or ""
};

/// A parameter's value as a flag or a keyword gives it: the full key and the double, carried
/// typed to the reader (config::Scenario::set_value), never through text.
struct ParamValue {
  std::string key;  ///< full key, "guidance.max_accel_mps2"
  double value = 0.0;
};

/// True when v is finite, inside the range, and whole for kInt (kBool: 0 or 1).
bool param_value_ok(const ParamSpec& p, double v) noexcept;
/// "a number in (0, 100] m/s^2", "an integer in [1, 1000]", "true or false".
std::string param_allowed_text(const ParamSpec& p);
/// Shortest text that reads back as the same double ("0.5", "1e-09", "nan").
std::string param_value_text(double v);
/// The one error text: "key 'K' = 'V' is invalid: expected <allowed>".
std::string param_error(const std::string& full_key, const std::string& value_text,
                        const ParamSpec& p);

/// One row of a module's table: the declaration plus where the value lives in Cfg.
template <class Cfg>
struct Param {
  ParamSpec spec;
  double* (*real)(Cfg&);   ///< kReal
  int* (*integer)(Cfg&);   ///< kInt
  bool* (*flag)(Cfg&);     ///< kBool
  std::uint64_t* (*seed)(Cfg&);  ///< kSeed

  /// The value as a double (bool: 0 or 1).
  double get(const Cfg& c) const noexcept {
    Cfg& m = const_cast<Cfg&>(c);  // the accessor only forms the field's address; read only
    switch (spec.type) {
      case ParamType::kReal: return *real(m);
      case ParamType::kInt: return static_cast<double>(*integer(m));
      case ParamType::kBool: return *flag(m) ? 1.0 : 0.0;
      case ParamType::kSeed: return static_cast<double>(*seed(m));
    }
    return 0.0;
  }
  /// Stores v (already checked with param_value_ok).
  void set(Cfg& c, double v) const noexcept {
    switch (spec.type) {
      case ParamType::kReal: *real(c) = v; break;
      case ParamType::kInt: *integer(c) = static_cast<int>(v); break;
      case ParamType::kBool: *flag(c) = v != 0.0; break;
      case ParamType::kSeed: *seed(c) = static_cast<std::uint64_t>(v); break;
    }
  }
};

/// A module's table: a view of a static array of rows.
template <class Cfg>
struct ParamTable {
  const Param<Cfg>* rows = nullptr;
  std::size_t count = 0;
  const Param<Cfg>* begin() const noexcept { return rows; }
  const Param<Cfg>* end() const noexcept { return rows + count; }
  std::size_t size() const noexcept { return count; }
};

/// Row p with the flag that sets it (and older spellings, comma-separated): the one place a
/// flag is declared; every executable that offers the parameter registers it from here.
template <class Cfg>
constexpr Param<Cfg> with_flag(Param<Cfg> p, const char* flag, const char* aliases = "") noexcept {
  p.spec.flag = flag;
  p.spec.aliases = aliases;
  return p;
}

template <class Cfg, std::size_t N>
constexpr ParamTable<Cfg> make_param_table(const Param<Cfg> (&rows)[N]) noexcept {
  return ParamTable<Cfg>{rows, N};
}

/// Empty when every parameter of c is valid, else param_error() of the first bad one, its
/// key prefixed with `prefix` (e.g. "guidance.").
template <class Cfg>
std::string validate_params(const ParamTable<Cfg>& table, const Cfg& c, const std::string& prefix) {
  for (const Param<Cfg>& p : table) {
    const double v = p.get(c);
    if (!param_value_ok(p.spec, v)) {
      return param_error(prefix + p.spec.key, param_value_text(v), p.spec);
    }
  }
  return std::string();
}

}  // namespace evade

// Row declarations. `path` is the field path inside Cfg, and becomes the key. It is a member
// path (`filter.gate_chi2_2dof`), which cannot be parenthesized in `&c.path`: hence the
// NOLINT(bugprone-macro-parentheses) on those lines.
#define EVADE_PARAM_REAL(Cfg, path, unit, lo, hi, lo_open, meaning)                          \
  ::evade::Param<Cfg> {                                                                      \
    {#path, unit, ::evade::ParamType::kReal, lo, hi, lo_open, meaning, nullptr, nullptr},     \
        [](Cfg& c) -> double* { return &c.path; }, /* NOLINT(bugprone-macro-parentheses) */    \
        nullptr, nullptr, nullptr                                                            \
  }
#define EVADE_PARAM_INT(Cfg, path, unit, lo, hi, meaning)                                    \
  ::evade::Param<Cfg> {                                                                      \
    {#path, unit, ::evade::ParamType::kInt, lo, hi, false, meaning, nullptr, nullptr},        \
        nullptr,                                                                             \
        [](Cfg& c) -> int* { return &c.path; }, /* NOLINT(bugprone-macro-parentheses) */       \
        nullptr, nullptr                                                                     \
  }
#define EVADE_PARAM_BOOL(Cfg, path, meaning)                                                 \
  ::evade::Param<Cfg> {                                                                      \
    {#path, "-", ::evade::ParamType::kBool, 0.0, 1.0, false, meaning, nullptr, nullptr},      \
        nullptr, nullptr,                                                                    \
        [](Cfg& c) -> bool* { return &c.path; }, /* NOLINT(bugprone-macro-parentheses) */      \
        nullptr                                                                              \
  }
#define EVADE_PARAM_SEED(Cfg, path, meaning)                                                 \
  ::evade::Param<Cfg> {                                                                      \
    {#path, "-", ::evade::ParamType::kSeed, 0.0, 18446744073709551615.0, false, meaning,      \
     nullptr, nullptr},                                                                      \
        nullptr, nullptr, nullptr,                                                           \
        [](Cfg& c) -> std::uint64_t* { return &c.path; } /* NOLINT(bugprone-macro-parentheses) */ \
  }
