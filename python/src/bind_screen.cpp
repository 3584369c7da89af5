// Bindings of `evade screen` (conjunction/screen_command.hpp): a scenario's objects, a CSV of
// objects or a synthetic population (paper or robust method), or a catalog moved by SGP4
// (optionally one primary against it). The request is built as the CLI builds it (the
// parameter keywords become the same key=value overrides, read through their declarations);
// the result is the command's JSON document, with the GIL released while screening.
#include <string>
#include <vector>

#include <nanobind/stl/map.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/commands/screen_command.hpp"

namespace evade::python {
namespace {

using namespace evade::conjunction;
using namespace evade::commands;

nb::object screen_objects(const std::string& scenario, const std::vector<std::string>& sets,
                          const ParamMap& params, const std::string& method, long population, long seed,
                          const std::string& objects_csv, bool trace, int threads) {
  ScreenObjectsSource src;
  src.method = method;
  src.population = population;
  src.seed = seed;
  if (population <= 0 && !objects_csv.empty()) {
    src.objects_csv_path = objects_csv;
    src.objects_csv_text = read_text_file(objects_csv, "objects_csv");
  }
  ScreenObjectsRequest req = read_screen_objects_request(load_scenario(scenario, sets, params), src);
  req.trace = trace;
  req.threads = threads;
  req.validate();
  nlohmann::json j;
  {
    nb::gil_scoped_release unlocked;
    j = to_json(run_screen_objects(req));
  }
  return json_to_python(j);
}

nb::object screen_catalog(const sgp4::Catalog& catalog, const std::string& source, long primary,
                          const ParamMap& params, const std::string& start_utc,
                          int threads, bool prefilter, bool path_filter, bool time_filter) {
  ScreenCatalogRequest req;
  req.source = source;
  req.primary_norad = primary;
  std::vector<ParamValue> values;
  for (const auto& [key, value] : params) values.push_back(ParamValue{key, value});
  apply_param_values(values, &req);
  req.start_utc = start_utc;
  req.threads = threads;
  req.prefilter = prefilter;
  req.path_filter = path_filter;
  req.time_filter = time_filter;
  req.validate();
  req.catalog = catalog;
  nlohmann::json j;
  {
    nb::gil_scoped_release unlocked;
    j = to_json(run_screen_catalog(req));
  }
  return json_to_python(j);
}

}  // namespace

void bind_screen(nb::module_& m) {
  m.def("screen_objects", &screen_objects, nb::arg("scenario"), nb::arg("sets"), nb::arg("params"),
        nb::arg("method"),
        nb::arg("population"), nb::arg("seed"), nb::arg("objects_csv"), nb::arg("trace"),
        nb::arg("threads"), "The JSON document of `evade screen` on objects.");
  m.def("screen_catalog", &screen_catalog, nb::arg("catalog"), nb::arg("source"), nb::arg("primary"),
        nb::arg("params"), nb::arg("start_utc"), nb::arg("threads"), nb::arg("prefilter"),
        nb::arg("path_filter"), nb::arg("time_filter"), "The JSON document of `evade screen --tle/--omm`.");
}

}  // namespace evade::python
