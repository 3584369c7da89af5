// Shared pieces of the evade._evade extension (docs/PYTHON.md): the error mapping, JSON to
// Python objects, scenarios and files read as the CLI reads them, numpy arrays owned by C++
// buffers. Not flight code: the binding of the library calls the CLI makes.
#pragma once

#include <cstddef>
#include <map>
#include <string>
#include <vector>

#include <nanobind/nanobind.h>
#include <nanobind/ndarray.h>
#include <nlohmann/json.hpp>

#include "evade/config/scenario.hpp"

namespace evade::python {

namespace nb = nanobind;

/// A numpy array over a heap buffer it owns (freed when the array is).
template <typename T>
using NumpyArray = nb::ndarray<nb::numpy, T>;

template <typename T>
NumpyArray<T> numpy_from_vector(std::vector<T> values, std::vector<std::size_t> shape) {
  auto* owned = new std::vector<T>(std::move(values));
  nb::capsule owner(owned, [](void* p) noexcept { delete static_cast<std::vector<T>*>(p); });
  return NumpyArray<T>(owned->data(), shape.size(), shape.data(), owner);
}

/// evade.InputError (a ValueError): what the CLI reports as "evade: error:" (config::ConfigError)
/// or "evade: invalid input:" (std::invalid_argument), with the same message.
void register_errors(nb::module_& m);

/// The Python value of a JSON document (dict, list, float, int, str, bool, None), numbers
/// exactly as the CLI prints them (shortest round-trip text, read back by json.loads).
nb::object json_to_python(const nlohmann::json& j);

/// The folder of the scenarios the package ships (names are looked up there first).
void set_package_scenario_dir(const std::string& dir);

/// Parameter keywords given (not None), full key -> the double given: they reach the reader
/// typed (config::Scenario::set_value), as the CLI's parameter flags do.
using ParamMap = std::map<std::string, double>;

/// The scenario as `--scenario NAME_OR_PATH --set k=v ... --FLAG v ...` loads it (a shipped
/// name found in the package's folder first, keeping the name as its source, as the CLI does).
config::Scenario load_scenario(const std::string& name_or_path, const std::vector<std::string>& sets,
                               const ParamMap& params = {});
/// Gives each of params to sc typed.
void give_params(const ParamMap& params, config::Scenario* sc);

/// The whole text of a file; std::invalid_argument "<what>: cannot open '<path>'" (the CLI's
/// message with the keyword's name for its flag).
std::string read_text_file(const std::string& path, const std::string& what);

/// The scenario `--scenario NAME` loads, read from `path` (the package's copy of a shipped
/// scenario) but named as the CLI names it, with the key=value overrides `sets` applied.
config::Scenario load_named_scenario(const std::string& name, const std::string& path,
                                     const std::vector<std::string>& sets);

void bind_sgp4(nb::module_& m);
void bind_screen(nb::module_& m);
void bind_assessment(nb::module_& m);
void bind_planners(nb::module_& m);
void bind_sim(nb::module_& m);
/// ThrustCommand and _GuidanceLaw (bind_guidance_law.cpp; registered by bind_sim).
void bind_thrust_command(nb::module_& m);
void bind_guidance_law(nb::module_& m);

}  // namespace evade::python
