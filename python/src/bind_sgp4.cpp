// Bindings of the SGP4 catalog calls: read a catalog (TLE/3LE, OMM KVN/XML, GP JSON/CSV;
// sgp4/catalog.hpp) and propagate N objects x T instants into numpy arrays the caller made
// (sgp4/propagate_grid.hpp), with the GIL released while SGP4 runs.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/core/epoch.hpp"
#include "evade/ccsds/catalog_formats.hpp"
#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/mean_elements.hpp"
#include "evade/sgp4/propagate_grid.hpp"
#include "evade/sgp4/sgp4.hpp"

namespace evade::python {
namespace {

using sgp4::Catalog;

std::vector<std::string> issue_messages(const Catalog& c) {
  std::vector<std::string> out;
  for (const sgp4::ReadIssue& is : c.issues) out.push_back(is.message());
  return out;
}

NumpyArray<std::int64_t> catalog_ids(const Catalog& c) {
  std::vector<std::int64_t> ids;
  for (const sgp4::MeanElements& m : c.objects) ids.push_back(m.norad_id);
  return numpy_from_vector(std::move(ids), {c.objects.size()});
}

NumpyArray<double> catalog_epochs(const Catalog& c) {
  std::vector<double> t;
  for (const sgp4::MeanElements& m : c.objects) t.push_back(sgp4::epoch_seconds_since_j2000(m));
  return numpy_from_vector(std::move(t), {c.objects.size()});
}

std::vector<std::string> catalog_names(const Catalog& c) {
  std::vector<std::string> out;
  for (const sgp4::MeanElements& m : c.objects) out.push_back(m.name);
  return out;
}

using TimesIn = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

using StatesOut = nb::ndarray<double, nb::ndim<3>, nb::c_contig, nb::device::cpu>;
using ErrorsOut = nb::ndarray<std::int32_t, nb::ndim<2>, nb::c_contig, nb::device::cpu>;

// Into the caller's arrays (numpy's own allocations: numpy advises huge pages for large ones,
// so the kernel's first touch of the states costs little; a fresh 40 MB array of 4 KiB pages
// costs about as much as SGP4 over it). r (N, T, 3), v the same or None, err (N, T).
double propagate_into(const Catalog& c, const std::string& start_utc, TimesIn t_s,
                      const std::string& frame, int threads, StatesOut r, std::optional<StatesOut> v,
                      ErrorsOut err) {
  sgp4::StateGridRequest req;
  req.start_j2000_s = sgp4::start_j2000_s_from_utc(start_utc, c);
  req.t_s = t_s.data();
  req.n_times = t_s.shape(0);
  req.j2000 = sgp4::frame_is_j2000(frame);
  req.threads = threads;
  sgp4::check_state_grid_request(c, req);
  const std::size_t n = c.objects.size();
  const auto fits = [&](std::size_t rows, std::size_t cols) { return rows == n && cols == req.n_times; };
  if (!fits(r.shape(0), r.shape(1)) || r.shape(2) != 3 || !fits(err.shape(0), err.shape(1)) ||
      (v && (!fits(v->shape(0), v->shape(1)) || v->shape(2) != 3)))
    throw std::invalid_argument("propagate: the output arrays must be (N, T, 3) and (N, T)");
  double* v_data = v ? v->data() : nullptr;
  {
    nb::gil_scoped_release unlocked;
    sgp4::propagate_grid(c, req, {r.data(), v_data, err.data()});
  }
  return req.start_j2000_s;
}

}  // namespace

void bind_sgp4(nb::module_& m) {
  nb::class_<Catalog>(m, "Catalog", "Element sets read from a catalog text (rejected entries named).")
      .def("__len__", [](const Catalog& c) { return c.objects.size(); })
      .def_prop_ro("ids", &catalog_ids, nb::rv_policy::move, "NORAD catalog numbers, in catalog order")
      .def_prop_ro("names", &catalog_names, "object names (empty when the format has none)")
      .def_prop_ro("epochs_j2000_s", &catalog_epochs, nb::rv_policy::move, "element epochs, UTC seconds since J2000")
      .def_prop_ro("bad_entries", [](const Catalog& c) { return c.bad_entries; },
                   "entries rejected by the reader")
      .def_prop_ro("issues", &issue_messages,
                   "one message per rejected entry: 'FILE:LINE:COL: expected ..., found ...'");
  m.def("read_catalog_text", &ccsds::read_catalog, nb::arg("text"), nb::arg("source"),
        "Reads a catalog's text (format guessed: TLE/3LE, OMM KVN/XML, GP JSON/CSV).");
  m.def("read_catalog_file", [](const std::string& path) {
        return ccsds::read_catalog(read_text_file(path, "catalog"), path);
      }, nb::arg("path"));
  m.def("sgp4_propagate_into", &propagate_into, nb::arg("catalog"), nb::arg("start_utc"),
        nb::arg("t_s"), nb::arg("frame"), nb::arg("threads"), nb::arg("r_m"), nb::arg("v_mps").none(),
        nb::arg("error"),
        "start_j2000_s; fills r_m[N,T,3], v_mps[N,T,3] (or None) and error[N,T] of every object at every instant.");
  m.def("sgp4_error_text", [](int code) -> std::string {
        if (code < 0 || code > static_cast<int>(sgp4::Sgp4Error::kDecayed)) return "unknown code";
        return sgp4::sgp4_error_text(static_cast<sgp4::Sgp4Error>(code));
      }, nb::arg("code"));
  m.def("utc_text", [](double j2000_s) {
        return format_calendar_utc(calendar_from_seconds_since_j2000(j2000_s));
      }, nb::arg("j2000_s"), "'YYYY-MM-DD hh:mm:ss.fffffffff' of UTC seconds since J2000");
}

}  // namespace evade::python
