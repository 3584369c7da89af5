// evade._evade: the nanobind extension under the `evade` Python package (docs/PYTHON.md).
// Each bind_*.cpp binds one group of the library calls the CLI makes; the Python modules of
// python/evade/ give them their keyword signatures, docstrings and result objects.
#include <nanobind/stl/string.h>

#include "bind_common.hpp"

namespace nb = nanobind;

NB_MODULE(_evade, m) {
  m.doc() = "evade C++ library calls (use the evade package, not this module)";
  m.attr("__version__") = EVADE_VERSION;
  evade::python::register_errors(m);
  m.def("set_package_scenario_dir", &evade::python::set_package_scenario_dir, nb::arg("dir"));
  evade::python::bind_sgp4(m);
  evade::python::bind_screen(m);
  evade::python::bind_assessment(m);
  evade::python::bind_planners(m);
  evade::python::bind_sim(m);
}
