// Error mapping, JSON conversion, scenarios and files for the extension (bind_common.hpp).
#include "bind_common.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nanobind/stl/string.h>

namespace evade::python {

void register_errors(nb::module_& m) {
  // Held for the life of the process and never released: a static nb::object would be
  // released after the interpreter has finalized (a fatal error at exit).
  static PyObject* input_error = PyErr_NewExceptionWithDoc(
      "evade._evade.InputError",
      "Bad input (a file, a scenario key, an argument): the message the evade CLI prints.",
      PyExc_ValueError, nullptr);
  if (input_error == nullptr) throw nb::python_error();
  m.attr("InputError") = nb::borrow(input_error);
  nb::register_exception_translator(
      [](const std::exception_ptr& p, void*) {
        try {
          std::rethrow_exception(p);
        } catch (const config::ConfigError& e) {
          PyErr_SetString(input_error, e.what());
        } catch (const std::invalid_argument& e) {
          PyErr_SetString(input_error, e.what());
        } catch (const std::domain_error& e) {
          PyErr_SetString(input_error, e.what());
        }
      },
      nullptr);
}

nb::object json_to_python(const nlohmann::json& j) {
  // Never released (see register_errors): the function outlives every call.
  static PyObject* loads = nb::object(nb::module_::import_("json").attr("loads")).release().ptr();
  return nb::borrow(loads)(j.dump());
}

namespace {
std::string& package_scenario_dir() {
  static std::string dir;  // set once by the package's __init__ (set_package_scenario_dir)
  return dir;
}
}  // namespace

void set_package_scenario_dir(const std::string& dir) { package_scenario_dir() = dir; }

void give_params(const ParamMap& params, config::Scenario* sc) {
  for (const auto& [key, value] : params) sc->set_value(ParamValue{key, value});
}

config::Scenario load_scenario(const std::string& name_or_path, const std::vector<std::string>& sets,
                               const ParamMap& params) {
  // A shipped name is read from the installed package first, under its name (the CLI's echo
  // "scenario": "seed2"); anything else is Scenario::load's (paths, $EVADE_SCENARIO_DIR, ...).
  const bool is_name = name_or_path.find('/') == std::string::npos &&
                       name_or_path.find(".yaml") == std::string::npos &&
                       name_or_path.find(".yml") == std::string::npos;
  const std::string shipped = package_scenario_dir() + "/" + name_or_path + ".yaml";
  config::Scenario s = is_name && !package_scenario_dir().empty() && std::ifstream(shipped).good()
                           ? config::Scenario::from_yaml_string(read_text_file(shipped, "scenario"), name_or_path)
                           : config::Scenario::load(name_or_path);
  for (const std::string& a : sets) s.apply_override(a);
  give_params(params, &s);
  return s;
}

// The scenario `--scenario NAME` loads, read from `path` (the package's copy of a shipped
// scenario) but named as the CLI names it, so that the JSON's "scenario" echoes the same text.
config::Scenario load_named_scenario(const std::string& name, const std::string& path,
                                     const std::vector<std::string>& sets) {
  config::Scenario sc = (path.empty() || path == name)
                            ? config::Scenario::load(name)
                            : config::Scenario::from_yaml_string(read_text_file(path, "scenario"),
                                                                 name);
  for (const std::string& kv : sets) sc.apply_override(kv);
  return sc;
}

std::string read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(what + ": cannot open '" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace evade::python
