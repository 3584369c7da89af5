// Bindings of the paper-000 guidance law (guidance/guidance_law.hpp; Yao & Wang 2012: thrust
// at max_accel_mps2 along −e_θ from the filtered line-of-sight angles) and its ThrustCommand.
//
// GuidanceLaw: the flight law itself, configured from the guidance.* keys of a scenario or of
// key=value overrides (read through the one parameter table, as the simulator reads them), and
// stepped from plain floats: step() converts its arguments without building numpy objects and
// returns the C++ ThrustCommand, whose fields are read lazily.
#include <chrono>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include <nanobind/stl/map.h>
#include <nanobind/stl/string.h>
#include <nanobind/stl/vector.h>

#include "bind_common.hpp"
#include "evade/config/read_params.hpp"
#include "evade/guidance/guidance_law.hpp"
#include "evade/guidance/guidance_params.hpp"

namespace evade::python {
namespace {

using guidance::GuidanceConfig;
using guidance::GuidanceLaw;
using guidance::GuidanceStatus;
using guidance::ThrustCommand;

/// The law and the sequence number of the measurements it is given.
struct BoundLaw {
  explicit BoundLaw(const GuidanceConfig& c) : law(c) {}
  GuidanceLaw law;
  std::int64_t seq = 0;
};

// The GuidanceConfig of the guidance.* keys of sc (the simulator's reader); strict: no other
// key may be present (an unknown key is named with the allowed ones).
GuidanceConfig read_guidance_config(const config::Scenario& sc, bool strict) {
  GuidanceConfig c;
  config::read_params(sc, "guidance.", guidance::guidance_params(), &c);
  if (strict) sc.check_all_used();
  return c;
}

// A scenario's guidance keys (name/path given) or the defaults with key=value overrides.
// params: the config dict's numbers, given typed (bind_common.hpp ParamMap).
void init_law(BoundLaw* self, const std::string& scenario, const std::string& path,
              const std::vector<std::string>& sets, const ParamMap& params,
              const std::string& source) {
  const bool from_scenario = !scenario.empty();
  config::Scenario sc = from_scenario ? load_named_scenario(scenario, path, {})
                                      : config::Scenario::empty(source);
  for (const std::string& kv : sets) sc.apply_override(kv);
  give_params(params, &sc);
  new (self) BoundLaw(read_guidance_config(sc, !from_scenario));
}

nb::dict config_dict(const BoundLaw& b) {
  nb::dict out;
  for (const Param<GuidanceConfig>& p : guidance::guidance_params()) {
    const double v = p.get(b.law.config());
    switch (p.spec.type) {
      case ParamType::kBool: out[p.spec.key] = v != 0.0; break;
      case ParamType::kInt: out[p.spec.key] = static_cast<long long>(v); break;
      default: out[p.spec.key] = v; break;
    }
  }
  return out;
}

nb::tuple tuple3(const Vec3& v) { return nb::make_tuple(v.x(), v.y(), v.z()); }

NumpyArray<double> numpy3(const Vec3& v) {
  return numpy_from_vector(std::vector<double>{v.x(), v.y(), v.z()}, {3});
}

nb::dict status_dict(const GuidanceStatus& s) {
  nb::dict d;
  d["utime_us"] = s.utime_us;
  d["t_s"] = 1e-6 * static_cast<double>(s.utime_us);
  d["mode"] = guidance::mode_name(s.mode);
  d["reason"] = guidance::reason_name(s.reason);
  d["track_valid"] = s.track_valid;
  d["los_rate_radps"] = s.los_rate_radps;
  d["los_rate_var_rad2ps2"] = s.los_rate_var_rad2ps2;
  d["e_theta_eci"] = numpy3(s.e_theta_eci);
  std::vector<double> cov(9);
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) cov[static_cast<std::size_t>(3 * i + j)] = s.e_theta_cov_eci(i, j);
  }
  d["e_theta_cov_eci"] = numpy_from_vector(std::move(cov), {3, 3});
  d["los_unit_eci"] = numpy3(s.los_unit_eci);
  d["zenith_flipped"] = s.zenith_flipped;
  d["fallback_direction"] = s.fallback_direction;
  d["zem_valid"] = s.zem_valid;
  d["zem_m"] = s.zem_m;
  d["t_go_valid"] = s.t_go_valid;
  d["t_go_s"] = s.t_go_s;
  d["dv_used_mps"] = s.dv_used_mps;
  d["burn_s"] = s.burn_s;
  d["cycles"] = s.cycles;
  d["meas_accepted"] = s.meas_accepted;
  d["meas_rejected"] = s.meas_rejected;
  d["meas_invalid"] = s.meas_invalid;
  d["filter_reinits"] = s.filter_reinits;
  d["watchdog_cycles"] = s.watchdog_cycles;
  return d;
}

[[noreturn]] void bad_vec3(const char* what) {
  PyErr_Clear();
  throw std::invalid_argument(std::string(what) + ": expected 3 numbers (a tuple, list or array)");
}

// A 3-vector argument: a tuple or list of 3 numbers without building anything (the fast
// path), any other sequence of 3 numbers (a numpy array) item by item.
Vec3 vec3_arg(nb::handle h, const char* what) {
  PyObject* o = h.ptr();
  Vec3 v;
  if ((PyTuple_CheckExact(o) && PyTuple_GET_SIZE(o) == 3) ||
      (PyList_CheckExact(o) && PyList_GET_SIZE(o) == 3)) {
    PyObject** items = PySequence_Fast_ITEMS(o);
    for (int i = 0; i < 3; ++i) {
      v[i] = PyFloat_AsDouble(items[i]);
      if (v[i] == -1.0 && PyErr_Occurred()) bad_vec3(what);
    }
    return v;
  }
  if (!PySequence_Check(o) || PySequence_Size(o) != 3) bad_vec3(what);
  for (Py_ssize_t i = 0; i < 3; ++i) {
    PyObject* item = PySequence_GetItem(o, i);
    if (item == nullptr) bad_vec3(what);
    v[static_cast<int>(i)] = PyFloat_AsDouble(item);
    Py_DECREF(item);
    if (v[static_cast<int>(i)] == -1.0 && PyErr_Occurred()) bad_vec3(what);
  }
  return v;
}

// Seconds to the law's microseconds; a clock must be finite (nav and measurements may not be:
// the law answers SAFE).
std::int64_t utime_us_of(double t_s, const char* what) {
  if (!std::isfinite(t_s) || std::fabs(t_s) > 9.0e12) {
    throw std::invalid_argument(std::string(what) + " = " + param_value_text(t_s) +
                                ": expected a finite time in seconds within +-9e12");
  }
  return std::llround(t_s * 1e6);
}

// One cycle of the law from plain arguments (the measurement's and the nav's times default
// to t_s, its sequence number counts the measurements given).
ThrustCommand step(BoundLaw& b, double t_s, nb::handle r_eci_m, nb::handle v_eci_mps,
                   bool has_measurement, double elevation_rad, double azimuth_rad,
                   double sigma_angle_rad, bool armed, bool has_rates,
                   double elevation_rate_radps, double azimuth_rate_radps,
                   double sigma_rate_radps, bool has_range, double range_m,
                   double range_rate_mps, bool meas_valid, double meas_t_s, bool nav_valid,
                   double nav_t_s) {
  const std::int64_t now_us = utime_us_of(t_s, "t_s");
  guidance::GuidanceInput in;
  in.nav.r_eci_m = vec3_arg(r_eci_m, "r_eci_m");
  in.nav.v_eci_mps = vec3_arg(v_eci_mps, "v_eci_mps");
  in.nav.utime_us = std::isnan(nav_t_s) ? now_us : utime_us_of(nav_t_s, "nav_t_s");
  in.nav.valid = nav_valid;
  in.armed = armed;
  in.has_measurement = has_measurement;
  if (has_measurement) {
    const std::int64_t meas_us = std::isnan(meas_t_s) ? now_us : utime_us_of(meas_t_s, "meas_t_s");
    in.meas = {meas_us,          ++b.seq,  elevation_rad,       azimuth_rad,
               sigma_angle_rad,  has_rates, elevation_rate_radps, azimuth_rate_radps,
               sigma_rate_radps, has_range, range_m,             range_rate_mps,
               meas_valid};
  }
  return b.law.step(in, now_us);
}

using Series1 = nb::ndarray<const double, nb::ndim<1>, nb::c_contig, nb::device::cpu>;

// N steps of the law inside C++ on the same inputs step() builds (angles with rates at t_s[k]),
// timed around the loop alone: the C++ cost that step() adds Python's to. Returns
// (elapsed seconds, commands in EVADE).
nb::tuple step_n(BoundLaw& b, Series1 t_s, Series1 el, Series1 az, Series1 el_rate,
                 Series1 az_rate, nb::handle r_eci_m, nb::handle v_eci_mps,
                 double sigma_angle_rad, double sigma_rate_radps) {
  const std::size_t n = t_s.shape(0);
  if (el.shape(0) != n || az.shape(0) != n || el_rate.shape(0) != n || az_rate.shape(0) != n) {
    throw std::invalid_argument("_step_n: the series differ in length");
  }
  const Vec3 r = vec3_arg(r_eci_m, "r_eci_m"), v = vec3_arg(v_eci_mps, "v_eci_mps");
  long evading = 0;
  double elapsed_s = 0.0;
  {
    nb::gil_scoped_release unlocked;
    const auto t0 = std::chrono::steady_clock::now();
    for (std::size_t k = 0; k < n; ++k) {
      guidance::GuidanceInput in;
      const std::int64_t now_us = std::llround(t_s.data()[k] * 1e6);
      in.nav = {now_us, r, v, true};
      in.armed = true;
      in.has_measurement = true;
      guidance::AnglesMeasurement& a = in.meas;
      a = {now_us, ++b.seq, el.data()[k], az.data()[k], sigma_angle_rad, true,
           el_rate.data()[k], az_rate.data()[k], sigma_rate_radps, false, 0.0, 0.0, true};
      evading += b.law.step(in, now_us).mode == guidance::GuidanceMode::kEvade ? 1 : 0;
    }
    elapsed_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  return nb::make_tuple(elapsed_s, evading);
}

// Interned names, so reading .mode / .reason allocates nothing.
// (Kept for the life of the process: never released, so nothing runs at interpreter exit.)
template <typename Enum, std::size_t N>
nb::object interned_name(Enum e, const char* (*name)(Enum) noexcept) {
  static PyObject* names[N] = {};
  const auto i = static_cast<std::size_t>(e);
  if (i >= N) return nb::str(name(e));
  if (names[i] == nullptr) names[i] = PyUnicode_InternFromString(name(e));
  return nb::borrow(names[i]);
}

nb::object mode_str(guidance::GuidanceMode m) {
  return interned_name<guidance::GuidanceMode, 5>(m, &guidance::mode_name);
}

nb::object reason_str(guidance::CommandReason r) {
  return interned_name<guidance::CommandReason, 12>(r, &guidance::reason_name);
}

std::string command_repr(const ThrustCommand& c) {
  std::ostringstream os;
  os.precision(17);
  os << "ThrustCommand(t_s=" << 1e-6 * static_cast<double>(c.utime_us) << ", mode='"
     << guidance::mode_name(c.mode) << "', reason='" << guidance::reason_name(c.reason)
     << "', accel_mps2=" << c.accel_mps2 << ", u_eci=(" << c.u_eci.x() << ", " << c.u_eci.y()
     << ", " << c.u_eci.z() << "))";
  return os.str();
}


const char* const kStepDoc =
    "One guidance cycle at t_s [s] (any epoch; the law's clock is in us).\n\n"
    "Positional, in this order (the fast path): t_s, r_eci_m, v_eci_mps (the satellite's nav "
    "state in ECI, 3 numbers each: a tuple is fastest), has_measurement (a new angle "
    "measurement since the last step), elevation_rad, azimuth_rad (paper 000 eq. 13-14: from "
    "the ECI equator towards +z, from +x towards +y), sigma_angle_rad (1 sigma), armed, then "
    "has_rates, elevation_rate_radps, azimuth_rate_radps, sigma_rate_radps (a rate-stabilised "
    "tracker), has_range, range_m, range_rate_mps, meas_valid (False: the sensor flags no "
    "detection), meas_t_s, nav_valid, nav_t_s (times of validity, default t_s). Keywords "
    "work too (a little slower than positional). Non-finite nav or measurement values are "
    "no error: the law answers SAFE.\n"
    "Returns a ThrustCommand: mode, reason, accel_mps2, u_eci (x, y, z).";

}  // namespace

void bind_thrust_command(nb::module_& m) {
  nb::class_<ThrustCommand>(m, "ThrustCommand",
                            "One guidance cycle's command (paper 000: |a| = max_accel_mps2 "
                            "along -e_theta in EVADE, zero otherwise).")
      .def_ro("utime_us", &ThrustCommand::utime_us, "time the command was computed [us]")
      .def_prop_ro("t_s",
                   [](const ThrustCommand& c) { return 1e-6 * static_cast<double>(c.utime_us); },
                   "time the command was computed [s]")
      .def_prop_ro("mode", [](const ThrustCommand& c) { return mode_str(c.mode); },
                   "STANDBY, TRACKING, EVADE, COAST or SAFE")
      .def_prop_ro("reason", [](const ThrustCommand& c) { return reason_str(c.reason); },
                   "why the command is what it is ('none' while evading normally)")
      .def_ro("accel_mps2", &ThrustCommand::accel_mps2, "commanded acceleration magnitude [m/s^2]")
      .def_prop_ro("u_eci", [](const ThrustCommand& c) { return tuple3(c.u_eci); },
                   "unit thrust direction in ECI (J2000), (x, y, z); zero without thrust")
      .def_prop_ro("accel_eci_mps2",
                   [](const ThrustCommand& c) { return tuple3(c.accel_mps2 * c.u_eci); },
                   "commanded acceleration vector in ECI [m/s^2], (x, y, z)")
      .def("__repr__", &command_repr);
}

void bind_guidance_law(nb::module_& m) {
  nb::class_<BoundLaw>(m, "_GuidanceLaw", "The paper-000 guidance law (use evade.GuidanceLaw).")
      .def("__init__", &init_law, nb::arg("scenario"), nb::arg("path"), nb::arg("sets"),
           nb::arg("params"), nb::arg("source"))
      .def("step", &step, nb::arg("t_s"), nb::arg("r_eci_m"), nb::arg("v_eci_mps"),
           nb::arg("has_measurement") = false, nb::arg("elevation_rad") = 0.0,
           nb::arg("azimuth_rad") = 0.0, nb::arg("sigma_angle_rad") = 0.0,
           nb::arg("armed") = true, nb::arg("has_rates") = false,
           nb::arg("elevation_rate_radps") = 0.0, nb::arg("azimuth_rate_radps") = 0.0,
           nb::arg("sigma_rate_radps") = 0.0, nb::arg("has_range") = false,
           nb::arg("range_m") = 0.0, nb::arg("range_rate_mps") = 0.0,
           nb::arg("meas_valid") = true, nb::arg("meas_t_s") = NAN, nb::arg("nav_valid") = true,
           nb::arg("nav_t_s") = NAN, kStepDoc)
      .def("reset", [](BoundLaw& b) { b.law.reset(); }, "back to STANDBY, no track, no dv used")
      .def("_status_dict", [](const BoundLaw& b) { return status_dict(b.law.status()); })
      .def("_config_dict", &config_dict)
      .def("_step_n", &step_n, nb::arg("t_s"), nb::arg("elevation_rad"), nb::arg("azimuth_rad"),
           nb::arg("elevation_rate_radps"), nb::arg("azimuth_rate_radps"), nb::arg("r_eci_m"),
           nb::arg("v_eci_mps"), nb::arg("sigma_angle_rad"), nb::arg("sigma_rate_radps"));
}

}  // namespace evade::python
