// Scenario files: YAML documents read through typed, range-checked accessors.
//
// Input is validated once, before anything runs, and trusted afterwards: every read names
// its key and its allowed range; a bad value throws ConfigError with a message naming the
// key, the value and what is allowed; after a command has read everything it needs,
// check_all_used() reports any key nobody read (a typo, or a key with the wrong unit suffix
// such as `accel` for `accel_mps2`). Keys carry their SI unit in their name.
//
// Keys are dot paths: "sensor.noise_rad"; a numeric component indexes a list:
// "objects.3.a_m". Overrides "--set key.path=value" parse value as YAML (so lists work:
// --set target.r_eci_m=[1,2,3]) and may add keys that the file omits.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "evade/core/param.hpp"
#include "evade/core/state.hpp"

namespace evade::config {

/// Bad configuration or input: the CLI turns it into exit code 2.
class ConfigError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Directories searched for a scenario given by name: $EVADE_SCENARIO_DIR, then (for an
/// installed executable) <prefix>/share/evade/scenarios beside its bin/, then the source
/// tree's scenarios/ (for the build tree's executables).
std::vector<std::string> scenario_search_dirs();

class Scenario {
 public:
  /// A name ("seed0") resolves to <dir>/<name>.yaml in scenario_search_dirs(); anything
  /// containing '/' or ending in .yaml/.yml is a path.
  static Scenario load(const std::string& name_or_path);
  static Scenario from_yaml_string(const std::string& yaml, const std::string& source_name);
  /// An empty scenario (every read falls back to its default).
  static Scenario empty(const std::string& source_name = "<defaults>");

  /// Applies "key.path=value".
  void apply_override(const std::string& assignment);
  /// A value given typed (a parameter flag, a Python keyword: evade/core/param.hpp
  /// ParamValue): get_param and get_double at v.key return this double, checked against the
  /// reader's range but never turned into text; it wins over the document and over any
  /// apply_override of the key (a later set_value of the key replaces it). Unread, it is
  /// reported by check_all_used() like an unknown key.
  void set_value(const ParamValue& v);

  bool has(const std::string& key) const;
  /// Number of elements of the list at key (0 when absent).
  std::size_t list_size(const std::string& key) const;

  double get_double(const std::string& key, double min, double max) const;
  double get_double(const std::string& key, double min, double max, double fallback) const;
  long get_int(const std::string& key, long min, long max) const;
  long get_int(const std::string& key, long min, long max, long fallback) const;
  bool get_bool(const std::string& key) const;
  bool get_bool(const std::string& key, bool fallback) const;
  std::string get_string(const std::string& key) const;
  std::string get_string(const std::string& key, const std::string& fallback) const;
  std::string get_enum(const std::string& key, const std::vector<std::string>& allowed) const;
  std::string get_enum(const std::string& key, const std::vector<std::string>& allowed,
                       const std::string& fallback) const;
  /// A list of exactly 3 finite numbers, each in [min, max].
  Vec3 get_vec3(const std::string& key, double min, double max) const;
  /// A list of finite numbers in [min, max] (any length >= min_len).
  std::vector<double> get_double_list(const std::string& key, double min, double max,
                                      std::size_t min_len = 1) const;

  /// A declared parameter (evade/core/param.hpp) at key: parsed by its type, checked against
  /// its range, and reported with param_error()'s text; `fallback` when the key is absent.
  double get_param(const std::string& key, const ParamSpec& spec, double fallback) const;
  /// A random seed: decimal digits, any value of std::uint64_t, read exactly.
  std::uint64_t get_seed(const std::string& key, std::uint64_t fallback) const;

  /// Marks a key as known without reading it (e.g. a comment field).
  void mark_used(const std::string& key) const;
  /// Throws ConfigError naming every key present in the document that was never read.
  void check_all_used() const;

  const std::string& source() const { return source_; }
  /// Every value read, with its final value (including defaults used), for echoing in
  /// results so a run says what it used.
  const nlohmann::json& used() const { return used_; }

 private:
  Scenario(nlohmann::json tree, std::string source);
  const nlohmann::json* find(const std::string& key) const;
  const double* typed(const std::string& key) const;  // set_value's value at key, or nullptr
  [[noreturn]] void fail(const std::string& key, const std::string& value,
                         const std::string& allowed) const;
  std::string scalar_text(const std::string& key, const nlohmann::json& node) const;
  void record(const std::string& key, const nlohmann::json& value) const;
  void record_param(const std::string& key, const ParamSpec& spec, double v) const;

  nlohmann::json tree_;  // YAML converted to JSON; every scalar kept as its text
  std::string source_;
  mutable nlohmann::json used_ = nlohmann::json::object();
  mutable std::vector<std::string> used_keys_;
  std::vector<ParamValue> typed_;  // set_value's, one per key
};

}  // namespace evade::config
