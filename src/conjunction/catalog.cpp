// Screening objects from YAML scenarios or CSV text, validated field by field (issue 6).
#include "evade/conjunction/catalog.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>

#include "evade/core/elements.hpp"

namespace evade::conjunction {
namespace {

SpaceObject from_elements(double a, double e, double i_deg, double raan_deg, double argp_deg,
                          double m_deg, const EarthModel& earth) {
  OrbitalElements oe;
  oe.a_m = a;
  oe.e = e;
  oe.i_rad = i_deg * kDegToRad;
  oe.raan_rad = raan_deg * kDegToRad;
  oe.argp_rad = argp_deg * kDegToRad;
  oe.true_anomaly_rad = true_from_mean_anomaly(m_deg * kDegToRad, e);
  SpaceObject o;
  o.state = state_from_elements(oe, earth.mu_m3ps2);
  return o;
}

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r");
  return s.substr(b, e - b + 1);
}

std::vector<std::string> split_csv(const std::string& line) {
  std::vector<std::string> out;
  std::string cur;
  std::istringstream is(line);
  while (std::getline(is, cur, ',')) out.push_back(trim(cur));
  if (!line.empty() && line.back() == ',') out.push_back("");
  return out;
}

std::invalid_argument not_a_number(long line_no, std::size_t k, const std::string& name,
                                   const std::string& cell) {
  return std::invalid_argument("CSV line " + std::to_string(line_no) + " (object " +
                               std::to_string(k) + "): " + name + " = '" + cell +
                               "' is not a finite number");
}

}  // namespace

std::vector<SpaceObject> objects_from_scenario(const config::Scenario& sc, const EarthModel& earth) {
  const std::size_t n = sc.list_size("objects");
  if (n == 0) throw config::ConfigError("objects: missing or empty (need a list of objects)");
  std::vector<SpaceObject> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string p = "objects." + std::to_string(k) + ".";
    SpaceObject o;
    if (sc.has(p + "r_eci_m") || sc.has(p + "v_eci_mps")) {
      o.state.r_eci_m = sc.get_vec3(p + "r_eci_m", -1e9, 1e9);
      o.state.v_eci_mps = sc.get_vec3(p + "v_eci_mps", -1e6, 1e6);
      OrbitShape s;
      try {
        s = orbit_shape(o.state, earth.mu_m3ps2);
      } catch (const std::invalid_argument& err) {
        throw config::ConfigError(p + "v_eci_mps: " + err.what());
      }
      if (!(s.perigee_radius_m > earth.re_m)) {
        throw config::ConfigError(p + "r_eci_m/v_eci_mps: perigee radius " +
                                  std::to_string(s.perigee_radius_m) +
                                  " m inside the Earth (allowed > re_m = " +
                                  std::to_string(earth.re_m) + " m)");
      }
    } else {
      const double a = sc.get_double(p + "a_m", 1.0, 1e10);
      const double e = sc.get_double(p + "e", 0.0, 1.0);
      if (!(e < 1.0)) {
        throw config::ConfigError(p + "e = " + std::to_string(e) + " outside [0, 1) (bound orbit)");
      }
      if (!(a * (1.0 - e) > earth.re_m)) {
        throw config::ConfigError(p + "a_m = " + std::to_string(a) + " with e = " +
                                  std::to_string(e) + ": perigee radius a(1-e) = " +
                                  std::to_string(a * (1.0 - e)) +
                                  " m inside the Earth (allowed > re_m = " +
                                  std::to_string(earth.re_m) + " m)");
      }
      const double inc = sc.get_double(p + "i_deg", 0.0, 180.0);
      const double raan = sc.get_double(p + "raan_deg", -360.0, 360.0);
      const double argp = sc.get_double(p + "argp_deg", -360.0, 360.0);
      const double m = sc.get_double(p + "mean_anomaly_deg", -360.0, 360.0);
      o = from_elements(a, e, inc, raan, argp, m, earth);
    }
    o.name = sc.get_string(p + "name", "object" + std::to_string(k));
    o.size_m = sc.get_double(p + "size_m", 0.0, 1e5);
    o.pos_error_m = sc.get_double(p + "pos_error_m", 0.0, 1e7);
    out.push_back(o);
  }
  validate_objects(out, earth);
  return out;
}

std::vector<SpaceObject> objects_from_csv(const std::string& text, const EarthModel& earth) {
  std::istringstream is(text);
  std::string line;
  std::vector<std::string> header;
  std::map<std::string, std::size_t> col;
  std::vector<SpaceObject> out;
  long line_no = 0;
  bool cartesian = false;
  while (std::getline(is, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto cells = split_csv(t);
    if (header.empty()) {
      header = cells;
      for (std::size_t c = 0; c < header.size(); ++c) col[header[c]] = c;
      const std::vector<std::string> kep = {"a_m", "e", "i_deg", "raan_deg", "argp_deg",
                                            "mean_anomaly_deg", "size_m", "pos_error_m"};
      const std::vector<std::string> car = {"x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps",
                                            "size_m", "pos_error_m"};
      cartesian = col.count("x_m") > 0;
      for (const auto& need : cartesian ? car : kep) {
        if (!col.count(need)) {
          throw std::invalid_argument("CSV header (line " + std::to_string(line_no) +
                                      "): missing column " + need);
        }
      }
      continue;
    }
    const std::size_t k = out.size();
    if (cells.size() != header.size()) {
      throw std::invalid_argument("CSV line " + std::to_string(line_no) + " (object " +
                                  std::to_string(k) + "): " + std::to_string(cells.size()) +
                                  " columns, header has " + std::to_string(header.size()));
    }
    auto num = [&](const std::string& name) {
      const std::string& s = cells[col.at(name)];
      char* end = nullptr;
      const double v = std::strtod(s.c_str(), &end);
      if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
        throw not_a_number(line_no, k, name, s);
      }
      return v;
    };
    auto bad = [&](const std::string& name, double v, const std::string& allowed) {
      std::ostringstream os;
      os << "CSV line " << line_no << " (object " << k << "): " << name << " = " << v
         << " outside " << allowed;
      throw std::invalid_argument(os.str());
    };
    SpaceObject o;
    if (cartesian) {
      o.state.r_eci_m = Vec3(num("x_m"), num("y_m"), num("z_m"));
      o.state.v_eci_mps = Vec3(num("vx_mps"), num("vy_mps"), num("vz_mps"));
    } else {
      const double a = num("a_m");
      const double e = num("e");
      if (!(a > 0.0)) bad("a_m", a, "(0, inf)");
      if (!(e >= 0.0 && e < 1.0)) bad("e", e, "[0, 1)");
      if (!(a * (1.0 - e) > earth.re_m)) bad("a_m", a, "a(1-e) > re_m (perigee inside the Earth)");
      const double inc = num("i_deg");
      if (!(inc >= 0.0 && inc <= 180.0)) bad("i_deg", inc, "[0, 180]");
      o = from_elements(a, e, inc, num("raan_deg"), num("argp_deg"), num("mean_anomaly_deg"), earth);
    }
    o.name = col.count("name") ? cells[col.at("name")] : "object" + std::to_string(k);
    o.size_m = num("size_m");
    o.pos_error_m = num("pos_error_m");
    if (!(o.size_m >= 0.0)) bad("size_m", o.size_m, "[0, inf)");
    if (!(o.pos_error_m >= 0.0)) bad("pos_error_m", o.pos_error_m, "[0, inf)");
    out.push_back(o);
  }
  validate_objects(out, earth);
  return out;
}

std::string events_to_csv(const std::vector<Conjunction>& events, const std::vector<SpaceObject>& objects) {
  std::ostringstream os;
  os.precision(17);
  os << "i,j,name_i,name_j,tca_s,miss_m,rel_speed_mps,collision,warning\n";
  for (const auto& c : events) {
    os << c.i << ',' << c.j << ',' << (c.i < objects.size() ? objects[c.i].name : "") << ','
       << (c.j < objects.size() ? objects[c.j].name : "") << ',' << c.tca_s << ',' << c.miss_m
       << ',' << c.rel_speed_mps << ',' << (c.collision ? 1 : 0) << ',' << (c.warning ? 1 : 0)
       << '\n';
  }
  return os.str();
}

}  // namespace evade::conjunction
