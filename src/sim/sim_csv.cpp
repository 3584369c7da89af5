// CSV time history of a simulation run (sim_csv.hpp); true ZEM (paper 000 eq. 7, 12).
#include "evade/sim/sim_csv.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>

namespace evade::sim {

const char* sim_csv_header() noexcept {
  return "t_s,sat_x_m,sat_y_m,sat_z_m,sat_vx_mps,sat_vy_mps,sat_vz_mps,deb_x_m,deb_y_m,deb_z_m,"
         "rel_x_m,rel_y_m,rel_z_m,range_m,range_rate_mps,los_rate_true_radps,zem_true_m,"
         "e_theta_true_x,e_theta_true_y,e_theta_true_z,has_meas,meas_el_rad,meas_az_rad,"
         "los_rate_est_radps,los_rate_est_sd_radps,e_theta_est_x,e_theta_est_y,e_theta_est_z,"
         "mode,reason,cmd_accel_mps2,cmd_dir_x,cmd_dir_y,cmd_dir_z,accel_x_mps2,accel_y_mps2,"
         "accel_z_mps2,dv_used_mps,fallback";
}

double zem_true_m(const SimSample& s) noexcept {
  return (s.range_rate_mps < 0.0)
             ? s.range_m * s.range_m * s.los_rate_true_radps / -s.range_rate_mps
             : NAN;
}

void write_sim_csv_row(std::ostream& os, const SimSample& s) {
  const Vec3 rel = s.debris.r_eci_m - s.satellite.r_eci_m;
  const double zem = zem_true_m(s);
  os << std::setprecision(15) << s.t_s;
  for (int i = 0; i < 3; ++i) os << ',' << s.satellite.r_eci_m[i];
  for (int i = 0; i < 3; ++i) os << ',' << s.satellite.v_eci_mps[i];
  for (int i = 0; i < 3; ++i) os << ',' << s.debris.r_eci_m[i];
  for (int i = 0; i < 3; ++i) os << ',' << rel[i];
  os << ',' << s.range_m << ',' << s.range_rate_mps << ',' << s.los_rate_true_radps << ','
     << zem;
  for (int i = 0; i < 3; ++i) os << ',' << s.e_theta_true_eci[i];
  os << ',' << (s.has_measurement ? 1 : 0) << ',' << s.meas.elevation_rad << ','
     << s.meas.azimuth_rad;
  os << ',' << s.status.los_rate_radps << ','
     << std::sqrt(std::max(s.status.los_rate_var_rad2ps2, 0.0));
  for (int i = 0; i < 3; ++i) os << ',' << s.status.e_theta_eci[i];
  os << ',' << guidance::mode_name(s.cmd.mode) << ',' << guidance::reason_name(s.cmd.reason)
     << ',' << s.cmd.accel_mps2;
  for (int i = 0; i < 3; ++i) os << ',' << s.cmd.u_eci[i];
  for (int i = 0; i < 3; ++i) os << ',' << s.accel_applied_eci_mps2[i];
  os << ',' << s.status.dv_used_mps << ',' << (s.status.fallback_direction ? 1 : 0) << '\n';
}

}  // namespace evade::sim
