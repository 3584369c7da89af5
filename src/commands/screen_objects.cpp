// Screening objects from YAML scenarios or CSV text, validated field by field (issue 6).
// Keplerian elements, from either, have the one reader's limits (config/read_elements.hpp).
#include "evade/commands/screen_objects.hpp"

#include <cmath>
#include <cstdlib>
#include <map>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "evade/config/read_elements.hpp"
#include "evade/core/elements.hpp"

namespace evade::commands {
namespace {

conjunction::SpaceObject from_elements(double a, double e, double i_deg, double raan_deg, double argp_deg,
                          double m_deg, const EarthModel& earth) {
  OrbitalElements oe;
  oe.a_m = a;
  oe.e = e;
  oe.i_rad = i_deg * kDegToRad;
  oe.raan_rad = raan_deg * kDegToRad;
  oe.argp_rad = argp_deg * kDegToRad;
  oe.true_anomaly_rad = true_from_mean_anomaly(m_deg * kDegToRad, e);
  conjunction::SpaceObject o;
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

// A CSV header: each column's index, and the form of the rows (Keplerian or Cartesian).
struct CsvColumns {
  std::vector<std::string> header;
  std::map<std::string, std::size_t> col;
  bool cartesian = false;
};

CsvColumns read_header(const std::vector<std::string>& cells, long line_no) {
  CsvColumns c;
  c.header = cells;
  for (std::size_t i = 0; i < cells.size(); ++i) c.col[cells[i]] = i;
  const std::vector<std::string> kep = {"a_m", "e", "i_deg", "raan_deg", "argp_deg",
                                        "mean_anomaly_deg", "size_m", "pos_error_m"};
  const std::vector<std::string> car = {"x_m", "y_m", "z_m", "vx_mps", "vy_mps", "vz_mps",
                                        "size_m", "pos_error_m"};
  c.cartesian = c.col.count("x_m") > 0;
  for (const auto& need : c.cartesian ? car : kep) {
    if (!c.col.count(need)) {
      throw std::invalid_argument("CSV header (line " + std::to_string(line_no) +
                                  "): missing column " + need);
    }
  }
  return c;
}

// One data row (object k on line line_no): its values by column name, and the error texts,
// which name the line, the object and the column.
class CsvRow {
 public:
  CsvRow(const CsvColumns& cols, std::vector<std::string> cells, long line_no, std::size_t k)
      : cols_(cols), cells_(std::move(cells)), line_no_(line_no), k_(k) {
    if (cells_.size() != cols_.header.size()) {
      throw std::invalid_argument(where() + std::to_string(cells_.size()) +
                                  " columns, header has " + std::to_string(cols_.header.size()));
    }
  }

  bool cartesian() const { return cols_.cartesian; }

  /// The cell of a column as a finite number.
  double num(const std::string& name) const {
    const std::string& s = cells_[cols_.col.at(name)];
    char* end = nullptr;
    const double v = std::strtod(s.c_str(), &end);
    if (s.empty() || end != s.c_str() + s.size() || !std::isfinite(v)) {
      throw std::invalid_argument(where() + name + " = '" + s + "' is not a finite number");
    }
    return v;
  }

  /// The cell of an orbital element, inside its one limit (config/read_elements.hpp).
  double element(const std::string& name, const config::ElementLimit& limit) const {
    const double v = num(name);
    if (!config::element_value_ok(limit, v)) bad(name, v, config::element_interval_text(limit));
    return v;
  }

  std::string name() const {
    return cols_.col.count("name") ? cells_[cols_.col.at("name")] : "object" + std::to_string(k_);
  }

  [[noreturn]] void bad(const std::string& name, double v, const std::string& allowed) const {
    std::ostringstream os;
    os << where() << name << " = " << v << " outside " << allowed;
    throw std::invalid_argument(os.str());
  }

 private:
  std::string where() const {
    return "CSV line " + std::to_string(line_no_) + " (object " + std::to_string(k_) + "): ";
  }

  const CsvColumns& cols_;
  std::vector<std::string> cells_;
  long line_no_;
  std::size_t k_;
};

conjunction::SpaceObject object_from_row(const CsvRow& row, const EarthModel& earth) {
  conjunction::SpaceObject o;
  if (row.cartesian()) {
    o.state.r_eci_m = Vec3(row.num("x_m"), row.num("y_m"), row.num("z_m"));
    o.state.v_eci_mps = Vec3(row.num("vx_mps"), row.num("vy_mps"), row.num("vz_mps"));
  } else {
    const double a = row.element("a_m", config::kSemiMajorAxisLimit);
    const double e = row.element("e", config::kEccentricityLimit);
    if (!config::perigee_above_surface(a, e, earth)) {
      row.bad("a_m", a, "a(1-e) > re_m (perigee inside the Earth)");
    }
    const double inc = row.element("i_deg", config::kInclinationLimit);
    const double raan = row.element("raan_deg", config::kAngleLimit);
    const double argp = row.element("argp_deg", config::kAngleLimit);
    const double m = row.element("mean_anomaly_deg", config::kAngleLimit);
    o = from_elements(a, e, inc, raan, argp, m, earth);
  }
  o.name = row.name();
  o.size_m = row.num("size_m");
  o.pos_error_m = row.num("pos_error_m");
  if (!(o.size_m >= 0.0)) row.bad("size_m", o.size_m, "[0, inf)");
  if (!(o.pos_error_m >= 0.0)) row.bad("pos_error_m", o.pos_error_m, "[0, inf)");
  return o;
}

}  // namespace

std::vector<conjunction::SpaceObject> objects_from_scenario(const config::Scenario& sc, const EarthModel& earth) {
  const std::size_t n = sc.list_size("objects");
  if (n == 0) throw config::ConfigError("objects: missing or empty (need a list of objects)");
  std::vector<conjunction::SpaceObject> out;
  out.reserve(n);
  for (std::size_t k = 0; k < n; ++k) {
    const std::string p = "objects." + std::to_string(k) + ".";
    conjunction::SpaceObject o;
    if (sc.has(p + "r_eci_m") || sc.has(p + "v_eci_mps")) {
      o.state.r_eci_m = sc.get_vec3(p + "r_eci_m", -1e9, 1e9);
      o.state.v_eci_mps = sc.get_vec3(p + "v_eci_mps", -1e6, 1e6);
      conjunction::OrbitShape s;
      try {
        s = conjunction::orbit_shape(o.state, earth.mu_m3ps2);
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
      const OrbitalElements oe =
          config::read_elements(sc, p, earth, config::OrbitPhase::kMeanAnomaly);
      o.state = state_from_elements(oe, earth.mu_m3ps2);
    }
    o.name = sc.get_string(p + "name", "object" + std::to_string(k));
    o.size_m = sc.get_double(p + "size_m", 0.0, 1e5);
    o.pos_error_m = sc.get_double(p + "pos_error_m", 0.0, 1e7);
    out.push_back(o);
  }
  conjunction::validate_objects(out, earth);
  return out;
}

std::vector<conjunction::SpaceObject> objects_from_csv(const std::string& text, const EarthModel& earth) {
  std::istringstream is(text);
  std::string line;
  CsvColumns cols;
  std::vector<conjunction::SpaceObject> out;
  long line_no = 0;
  while (std::getline(is, line)) {
    ++line_no;
    const std::string t = trim(line);
    if (t.empty() || t[0] == '#') continue;
    const auto cells = split_csv(t);
    if (cols.header.empty()) {
      cols = read_header(cells, line_no);
    } else {
      out.push_back(object_from_row(CsvRow(cols, cells, line_no, out.size()), earth));
    }
  }
  conjunction::validate_objects(out, earth);
  return out;
}

std::string events_to_csv(const std::vector<conjunction::Conjunction>& events, const std::vector<conjunction::SpaceObject>& objects) {
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

}  // namespace evade::commands
