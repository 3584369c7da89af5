// Local orbital frames (RSW, VVLH) and relative-state transforms with the transport term
// omega x rho. Vallado 4th ed. sec. 3.3 (RSW); CCSDS LVLH for VVLH. Conventions in the header.
#include "evade/core/frames.hpp"

#include <stdexcept>

namespace evade {
namespace {

void require_valid(const StateEci& s) {
  if (!s.r_eci_m.allFinite() || !s.v_eci_mps.allFinite())
    throw std::invalid_argument("local frame: non-finite chief state");
  if (s.r_eci_m.cross(s.v_eci_mps).norm() <= 0.0)
    throw std::invalid_argument("local frame: chief r x v = 0, frame undefined");
}

}  // namespace

Mat3 rotation_eci_to_rsw(const StateEci& chief) {
  require_valid(chief);
  const Vec3 r_hat = chief.r_eci_m.normalized();
  const Vec3 w_hat = chief.r_eci_m.cross(chief.v_eci_mps).normalized();
  const Vec3 s_hat = w_hat.cross(r_hat);
  Mat3 c;
  c.row(0) = r_hat.transpose();
  c.row(1) = s_hat.transpose();
  c.row(2) = w_hat.transpose();
  return c;
}

Mat3 rotation_rsw_to_vvlh() {
  Mat3 m;
  m << 0, 1, 0,   // x_vvlh = S
      0, 0, -1,   // y_vvlh = -W
      -1, 0, 0;   // z_vvlh = -R
  return m;
}

Mat3 rotation_eci_to_vvlh(const StateEci& chief) {
  return rotation_rsw_to_vvlh() * rotation_eci_to_rsw(chief);
}

Vec3 frame_rate_eci_radps(const StateEci& chief) {
  return chief.r_eci_m.cross(chief.v_eci_mps) / chief.r_eci_m.squaredNorm();
}

Vec6 relative_rsw_from_eci(const StateEci& chief, const StateEci& deputy) {
  const Mat3 c = rotation_eci_to_rsw(chief);
  const Vec3 w = frame_rate_eci_radps(chief);
  const Vec3 dr = deputy.r_eci_m - chief.r_eci_m;
  const Vec3 dv = deputy.v_eci_mps - chief.v_eci_mps;
  Vec6 x;
  x << c * dr, c * (dv - w.cross(dr));
  return x;
}

StateEci eci_from_relative_rsw(const StateEci& chief, const Vec6& rel) {
  const Mat3 ct = rotation_eci_to_rsw(chief).transpose();
  const Vec3 w = frame_rate_eci_radps(chief);
  const Vec3 dr = ct * rel.head<3>();
  const Vec3 dv = ct * rel.tail<3>() + w.cross(dr);
  return {chief.r_eci_m + dr, chief.v_eci_mps + dv};
}

Vec6 relative_vvlh_from_eci(const StateEci& chief, const StateEci& deputy) {
  const Vec6 rsw = relative_rsw_from_eci(chief, deputy);
  const Mat3 m = rotation_rsw_to_vvlh();
  Vec6 x;
  x << m * rsw.head<3>(), m * rsw.tail<3>();
  return x;
}

StateEci eci_from_relative_vvlh(const StateEci& chief, const Vec6& rel_vvlh) {
  const Mat3 mt = rotation_rsw_to_vvlh().transpose();
  Vec6 rsw;
  rsw << mt * rel_vvlh.head<3>(), mt * rel_vvlh.tail<3>();
  return eci_from_relative_rsw(chief, rsw);
}

}  // namespace evade
