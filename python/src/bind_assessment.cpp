// Bindings of the assessment calls: `evade assess` (assessment/assess_command.hpp: 2D, Chan,
// max, 3D-Nc, Monte Carlo and the recommended Pc), `evade plan cam`
// (assessment/plan_cam_command.hpp, with the BurnPlan the command publishes:
// cam_burn_plan.hpp) and the CCSDS CDM (cdm.hpp, cdm_kvn.hpp, cdm_xml.hpp): read from a file
// or a text, its fields, written as KVN or XML. Requests are built as the CLI builds them and
// the results are the commands' JSON documents; the GIL is released while they run. The
// Monte Carlo runs on this process's threads (McExecution without a runner: the threaded
// block runner), which gives the CLI's numbers for the same seed: a result depends only on
// the seed and the blocks run (monte_carlo_pc.hpp).
#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include <nanobind/stl/map.h>
#include <nanobind/stl/optional.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/tuple.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/commands/assess_command.hpp"
#include "evade/cam/cam_burn_plan.hpp"
#include "evade/ccsds/cdm.hpp"
#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"
#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/commands/plan_cam_command.hpp"
#include "evade/core/epoch.hpp"

namespace evade::python {
namespace {

using namespace evade::assessment;
using namespace evade::cam;
using namespace evade::commands;
using namespace evade::ccsds;

/// A CDM argument as the Python layer hands it: a file's path (read here, as the CLI's
/// --cdm), or a text with the name the result gives it.
struct CdmArg {
  std::string path, text, name;
  bool given() const { return !path.empty() || !name.empty(); }
  std::string read() const { return path.empty() ? text : read_text_file(path, "--cdm"); }
  std::string source() const { return path.empty() ? name : path; }
};

// The numbers of "a<sep>b<sep>..." as the CLI reads a number list (strtod of each field; empty
// when a field is not a whole number or overflows).
std::vector<double> number_list(const std::string& text, char sep) {
  std::vector<double> out;
  std::size_t begin = 0;
  for (;;) {
    const std::size_t end = std::min(text.find(sep, begin), text.size());
    const std::string field = text.substr(begin, end - begin);
    char* stop = nullptr;
    errno = 0;
    const double x = std::strtod(field.c_str(), &stop);
    const bool overflow = errno == ERANGE && std::isinf(x);
    if (field.empty() || stop != field.c_str() + field.size() || overflow) return {};
    out.push_back(x);
    if (end == text.size()) return out;
    begin = end + 1;
  }
}

// The CDM's assessment tables come from an empty scenario with the overrides (the CLI's --cdm).
config::Scenario cdm_scenario(const std::vector<std::string>& sets, const ParamMap& params = {}) {
  config::Scenario sc = config::Scenario::empty("--cdm");
  for (const std::string& a : sets) sc.apply_override(a);
  give_params(params, &sc);
  return sc;
}

AssessRequest plane_request(const std::string& plane) {
  const std::vector<double> v = number_list(plane, ',');
  if (v.size() != 5) {
    throw std::invalid_argument("--encounter-plane: expected MISS_X_M,MISS_Y_M,SIGMA_X_M,"
                                "SIGMA_Y_M,HBR_M, found '" + plane + "'");
  }
  return encounter_plane_request(PrincipalEncounter{v[0], v[1], v[2], v[3]}, v[4]);
}

AssessRequest assess_request(const std::string& scenario, const std::vector<std::string>& sets,
                             const ParamMap& params, const CdmArg& cdm, double hbr_m,
                             const std::string& plane) {
  const int sources = !scenario.empty() + cdm.given() + !plane.empty();
  if (sources != 1)
    throw std::invalid_argument("give exactly one of --scenario, --cdm, --encounter-plane");
  if (!plane.empty() && (!sets.empty() || !params.empty())) {
    throw std::invalid_argument("--set and --window-s do not apply to --encounter-plane (no "
                                "states: the 2D Pc only)");
  }
  if (!plane.empty()) return plane_request(plane);
  if (!scenario.empty()) return read_assess_request(load_scenario(scenario, sets, params));
  return read_assess_request_cdm(cdm_scenario(sets, params), cdm.read(), cdm.source(), hbr_m);
}

std::tuple<nb::object, std::vector<std::string>> assess(
    const std::string& scenario, const std::vector<std::string>& sets, const ParamMap& params,
    const std::string& cdm_path, const std::string& cdm_text, const std::string& cdm_name,
    double hbr_m, const std::string& plane, long mc, std::uint64_t seed, int threads) {
  AssessRequest req =
      assess_request(scenario, sets, params, CdmArg{cdm_path, cdm_text, cdm_name}, hbr_m, plane);
  req.mc_samples = mc;
  req.mc_seed = seed;
  // As the CLI on one process: threads (0: every core), a wave of that many blocks.
  req.mc_exec.threads =
      threads > 0 ? threads : static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  req.mc_exec.wave_blocks = req.mc_exec.threads;
  nlohmann::json j;
  std::vector<std::string> warnings;
  {
    nb::gil_scoped_release unlocked;
    const AssessResult r = run_assess(req);
    j = to_json(r);
    warnings = assess_warnings(r);
  }
  return {json_to_python(j), warnings};
}

// --sweep-lead A:B:N.
CamLeadSweep parse_sweep(const std::string& text) {
  const std::vector<double> v = number_list(text, ':');
  if (v.size() != 3 || !(v[2] >= 1.0 && v[2] <= 10000.0 && v[2] == std::floor(v[2])) ||
      !(v[0] <= v[1]))
    throw std::invalid_argument("--sweep-lead: expected A:B:N with A <= B and N in [1, 10000], found '" +
                                text + "'");
  return {v[0], v[1], static_cast<int>(v[2])};
}

nb::tuple plan_cam(const std::string& scenario, const std::vector<std::string>& sets,
                   const std::string& cdm_path, const std::string& cdm_text,
                   const std::string& cdm_name, double hbr_m, const CamRequest& cam,
                   const std::string& sweep, std::int64_t plan_id) {
  const CdmArg cdm{cdm_path, cdm_text, cdm_name};
  if (scenario.empty() == !cdm.given()) throw std::invalid_argument("give exactly one of --scenario, --cdm");
  PlanCamRequest req =
      !scenario.empty() ? read_plan_cam_request(load_scenario(scenario, sets))
                        : read_plan_cam_request_cdm(cdm_scenario(sets), cdm.read(), cdm.source(), hbr_m);
  req.cam = cam;
  if (!sweep.empty()) req.sweep = parse_sweep(sweep);
  nlohmann::json j;
  std::optional<BurnPlan> plan;
  {
    nb::gil_scoped_release unlocked;
    const PlanCamResult r = run_plan_cam(req);
    j = to_json(r);
    // A sweep, or no maneuver needed: nothing to fly.
    if (r.plan && r.plan->maneuver_needed) plan = make_cam_burn_plan(*r.plan, plan_id);
  }
  return nb::make_tuple(json_to_python(j), plan ? nb::cast(*plan) : nb::none());
}

// One section's keywords in order: (keyword, value, unit); object -1 for the header (section
// "header") and the relative metadata/data (section "relative").
std::vector<std::tuple<std::string, std::string, std::string>> cdm_items(const Cdm& c,
                                                                        const std::string& section,
                                                                        int object) {
  const CdmSection* s = nullptr;
  if (section == "header") s = &c.header;
  else if (section == "relative") s = &c.relative;
  else if (object < 0 || object > 1) throw std::invalid_argument("CDM object must be 0 or 1");
  else if (section == "metadata") s = &c.object[object].metadata;
  else if (section == "od_parameters") s = &c.object[object].od_parameters;
  else if (section == "additional_parameters") s = &c.object[object].additional_parameters;
  else if (section == "state_vector") s = &c.object[object].state_vector;
  else if (section == "covariance") s = &c.object[object].covariance;
  if (s == nullptr) throw std::invalid_argument("CDM section '" + section + "' is unknown");
  std::vector<std::tuple<std::string, std::string, std::string>> out;
  for (const CdmItem& it : s->items) out.emplace_back(it.key, it.value, it.unit);
  return out;
}

void check_object(int i) {
  if (i < 0 || i > 1) throw std::invalid_argument("CDM object must be 0 or 1");
}

NumpyArray<double> vec3_numpy(const Vec3& v) { return numpy_from_vector<double>({v[0], v[1], v[2]}, {3}); }

NumpyArray<double> matrix_numpy(const Eigen::MatrixXd& a) {
  std::vector<double> out;
  for (Eigen::Index r = 0; r < a.rows(); ++r)
    for (Eigen::Index c = 0; c < a.cols(); ++c) out.push_back(a(r, c));
  return numpy_from_vector(std::move(out), {static_cast<std::size_t>(a.rows()),
                                            static_cast<std::size_t>(a.cols())});
}

std::vector<std::string> cdm_notes(const Cdm& c) {
  std::vector<std::string> notes = cdm_unit_notes(c);
  for (const std::string& n : cdm_covariance_notes(c)) notes.push_back(n);
  return notes;
}

void bind_cdm(nb::module_& m) {
  nb::class_<Cdm>(m, "CdmNative", "A validated CCSDS CDM (508.0-B-1), every keyword as text.")
      .def("__eq__", [](const Cdm& a, const Cdm& b) { return a == b; })
      .def("to_kvn", &write_cdm_kvn)
      .def("to_xml", &write_cdm_xml)
      .def("items", &cdm_items, nb::arg("section"), nb::arg("object"))
      .def("r_m", [](const Cdm& c, int i) { check_object(i); return vec3_numpy(cdm_state(c, i).r_eci_m); },
           nb::arg("object"), "position in the object's REF_FRAME [m]")
      .def("v_mps", [](const Cdm& c, int i) { check_object(i); return vec3_numpy(cdm_state(c, i).v_eci_mps); },
           nb::arg("object"), "velocity in the object's REF_FRAME [m/s]")
      .def("cov_rtn", [](const Cdm& c, int i) { check_object(i); return matrix_numpy(cdm_cov_rtn(c, i)); },
           nb::arg("object"), "6x6 RTN covariance [m^2, m^2/s, m^2/s^2]")
      .def("cov_rtn_full", [](const Cdm& c, int i) { check_object(i); return matrix_numpy(cdm_cov_rtn_full(c, i)); },
           nb::arg("object"))
      .def("cov_rows", [](const Cdm& c, int i) { check_object(i); return cdm_cov_rows(c, i); }, nb::arg("object"))
      .def("notes", &cdm_notes)
      .def("tca_j2000_s", [](const Cdm& c) {
        return seconds_since_j2000_from_calendar(parse_calendar_utc(cdm_value(c.relative, "TCA")));
      });
  m.def("cdm_read_text", &ccsds::read_cdm_text, nb::arg("text"), "A CDM's text (KVN, or XML when it starts with '<').");
  m.def("cdm_read_file", [](const std::string& path) { return ccsds::read_cdm_text(read_text_file(path, "cdm")); },
        nb::arg("path"));
}

}  // namespace

void bind_assessment(nb::module_& m) {
  bind_cdm(m);
  nb::class_<CamRequest>(m, "CamRequest")
      .def(nb::init<>())
      .def_rw("lead_s", &CamRequest::lead_s)
      .def_rw("pc_max", &CamRequest::pc_max)
      .def_rw("min_miss_m", &CamRequest::min_miss_m)
      .def_rw("along_track_only", &CamRequest::along_track_only);
  m.def("assess", &assess, nb::arg("scenario"), nb::arg("sets"), nb::arg("params"),
        nb::arg("cdm_path"),
        nb::arg("cdm_text"), nb::arg("cdm_name"), nb::arg("hbr_m"), nb::arg("encounter_plane"),
        nb::arg("mc"), nb::arg("seed"), nb::arg("threads"),
        "(JSON of `evade assess`, the warnings it prints on stderr)");
  m.def("plan_cam", &plan_cam, nb::arg("scenario"), nb::arg("sets"), nb::arg("cdm_path"),
        nb::arg("cdm_text"), nb::arg("cdm_name"), nb::arg("hbr_m"), nb::arg("cam"),
        nb::arg("sweep_lead"), nb::arg("plan_id"),
        "(JSON of `evade plan cam`, its BurnPlan or None)");
}

}  // namespace evade::python
