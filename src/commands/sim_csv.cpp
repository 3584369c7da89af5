// CSV time history of a simulation run (sim_csv.hpp); true ZEM (paper 000 eq. 7, 12). The
// columns are one table (sim_csv_columns): the header, the rows and the Python binding's
// arrays are all read from it.
#include "evade/commands/sim_csv.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace evade::commands {
namespace {

Vec3 rel_eci_m(const sim::SimSample& s) { return s.debris.r_eci_m - s.satellite.r_eci_m; }

using S = const sim::SimSample&;
// Each entry: the column's name (with its unit) and its value, a number or a name.
constexpr SimCsvColumn kColumns[] = {
    {"t_s", [](S s) { return s.t_s; }, nullptr},
    {"sat_x_m", [](S s) { return s.satellite.r_eci_m.x(); }, nullptr},
    {"sat_y_m", [](S s) { return s.satellite.r_eci_m.y(); }, nullptr},
    {"sat_z_m", [](S s) { return s.satellite.r_eci_m.z(); }, nullptr},
    {"sat_vx_mps", [](S s) { return s.satellite.v_eci_mps.x(); }, nullptr},
    {"sat_vy_mps", [](S s) { return s.satellite.v_eci_mps.y(); }, nullptr},
    {"sat_vz_mps", [](S s) { return s.satellite.v_eci_mps.z(); }, nullptr},
    {"deb_x_m", [](S s) { return s.debris.r_eci_m.x(); }, nullptr},
    {"deb_y_m", [](S s) { return s.debris.r_eci_m.y(); }, nullptr},
    {"deb_z_m", [](S s) { return s.debris.r_eci_m.z(); }, nullptr},
    {"rel_x_m", [](S s) { return rel_eci_m(s).x(); }, nullptr},
    {"rel_y_m", [](S s) { return rel_eci_m(s).y(); }, nullptr},
    {"rel_z_m", [](S s) { return rel_eci_m(s).z(); }, nullptr},
    {"range_m", [](S s) { return s.range_m; }, nullptr},
    {"range_rate_mps", [](S s) { return s.range_rate_mps; }, nullptr},
    {"los_rate_true_radps", [](S s) { return s.los_rate_true_radps; }, nullptr},
    {"zem_true_m", [](S s) { return zem_true_m(s); }, nullptr},
    {"e_theta_true_x", [](S s) { return s.e_theta_true_eci.x(); }, nullptr},
    {"e_theta_true_y", [](S s) { return s.e_theta_true_eci.y(); }, nullptr},
    {"e_theta_true_z", [](S s) { return s.e_theta_true_eci.z(); }, nullptr},
    {"has_meas", [](S s) { return s.has_measurement ? 1.0 : 0.0; }, nullptr},
    {"meas_el_rad", [](S s) { return s.meas.elevation_rad; }, nullptr},
    {"meas_az_rad", [](S s) { return s.meas.azimuth_rad; }, nullptr},
    {"los_rate_est_radps", [](S s) { return s.status.los_rate_radps; }, nullptr},
    {"los_rate_est_sd_radps", [](S s) { return std::sqrt(std::max(s.status.los_rate_var_rad2ps2, 0.0)); },
     nullptr},
    {"e_theta_est_x", [](S s) { return s.status.e_theta_eci.x(); }, nullptr},
    {"e_theta_est_y", [](S s) { return s.status.e_theta_eci.y(); }, nullptr},
    {"e_theta_est_z", [](S s) { return s.status.e_theta_eci.z(); }, nullptr},
    {"mode", nullptr, [](S s) { return guidance::mode_name(s.cmd.mode); }},
    {"reason", nullptr, [](S s) { return guidance::reason_name(s.cmd.reason); }},
    {"cmd_accel_mps2", [](S s) { return s.cmd.accel_mps2; }, nullptr},
    {"cmd_dir_x", [](S s) { return s.cmd.u_eci.x(); }, nullptr},
    {"cmd_dir_y", [](S s) { return s.cmd.u_eci.y(); }, nullptr},
    {"cmd_dir_z", [](S s) { return s.cmd.u_eci.z(); }, nullptr},
    {"accel_x_mps2", [](S s) { return s.accel_applied_eci_mps2.x(); }, nullptr},
    {"accel_y_mps2", [](S s) { return s.accel_applied_eci_mps2.y(); }, nullptr},
    {"accel_z_mps2", [](S s) { return s.accel_applied_eci_mps2.z(); }, nullptr},
    {"dv_used_mps", [](S s) { return s.status.dv_used_mps; }, nullptr},
    {"fallback", [](S s) { return s.status.fallback_direction ? 1.0 : 0.0; }, nullptr},
};

std::string header_text() {
  std::string h;
  for (const SimCsvColumn& c : kColumns) h.append(h.empty() ? "" : ",").append(c.name);
  return h;
}

}  // namespace

const SimCsvColumn* sim_csv_columns(std::size_t* count) noexcept {
  *count = sizeof kColumns / sizeof kColumns[0];
  return kColumns;
}

const char* sim_csv_header() noexcept {
  static const std::string h = header_text();
  return h.c_str();
}

double zem_true_m(const sim::SimSample& s) noexcept {
  return (s.range_rate_mps < 0.0)
             ? s.range_m * s.range_m * s.los_rate_true_radps / -s.range_rate_mps
             : NAN;
}

void write_sim_csv_row(std::ostream& os, const sim::SimSample& s) {
  os << std::setprecision(15);
  bool first = true;
  for (const SimCsvColumn& c : kColumns) {
    if (!first) os << ',';
    first = false;
    if (c.number != nullptr) os << c.number(s);
    else os << c.text(s);
  }
  os << '\n';
}

}  // namespace evade::commands
