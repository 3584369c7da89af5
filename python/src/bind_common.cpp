// Error mapping, JSON conversion, scenarios and files for the extension (bind_common.hpp).
#include "bind_common.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

#include <nanobind/stl/string.h>

namespace evade::python {

void register_errors(nb::module_& m) {
  static nb::object input_error;  // the type lives as long as the module
  input_error = nb::steal(PyErr_NewExceptionWithDoc(
      "evade._evade.InputError",
      "Bad input (a file, a scenario key, an argument): the message the evade CLI prints.",
      PyExc_ValueError, nullptr));
  m.attr("InputError") = input_error;
  nb::register_exception_translator(
      [](const std::exception_ptr& p, void*) {
        try {
          std::rethrow_exception(p);
        } catch (const config::ConfigError& e) {
          PyErr_SetString(input_error.ptr(), e.what());
        } catch (const std::invalid_argument& e) {
          PyErr_SetString(input_error.ptr(), e.what());
        } catch (const std::domain_error& e) {
          PyErr_SetString(input_error.ptr(), e.what());
        }
      },
      nullptr);
}

nb::object json_to_python(const nlohmann::json& j) {
  static nb::object loads = nb::module_::import_("json").attr("loads");
  return loads(j.dump());
}

config::Scenario load_scenario(const std::string& name_or_path, const std::vector<std::string>& sets) {
  config::Scenario s = config::Scenario::load(name_or_path);
  for (const std::string& a : sets) s.apply_override(a);
  return s;
}

std::string read_text_file(const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument(what + ": cannot open '" + path + "'");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

}  // namespace evade::python
