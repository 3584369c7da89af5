// Object validation and orbit shape for the conjunction filters (paper 002 eq. 1-2 inputs).
#include "evade/conjunction/types.hpp"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace evade::conjunction {

OrbitShape orbit_shape(const StateEci& s, double mu_m3ps2) {
  if (!s.r_eci_m.allFinite() || !s.v_eci_mps.allFinite()) {
    throw std::invalid_argument("orbit_shape: non-finite state");
  }
  const double r = s.r_eci_m.norm();
  if (!(r > 0.0)) throw std::invalid_argument("orbit_shape: zero position vector");
  const double inv_a = 2.0 / r - s.v_eci_mps.squaredNorm() / mu_m3ps2;
  const Vec3 h = s.r_eci_m.cross(s.v_eci_mps);
  const Vec3 e_vec = s.v_eci_mps.cross(h) / mu_m3ps2 - s.r_eci_m / r;
  const double e = e_vec.norm();
  if (!(inv_a > 0.0) || !(e < 1.0)) {
    std::ostringstream os;
    os << "orbit is not bound: e = " << e << " (allowed [0, 1))";
    throw std::invalid_argument(os.str());
  }
  OrbitShape o;
  o.a_m = 1.0 / inv_a;
  o.e = e;
  o.perigee_radius_m = o.a_m * (1.0 - e);
  o.apogee_radius_m = o.a_m * (1.0 + e);
  return o;
}

void validate_objects(const std::vector<SpaceObject>& objects, const EarthModel& earth) {
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const SpaceObject& o = objects[k];
    auto fail = [&](const std::string& field, double value, const std::string& allowed) {
      std::ostringstream os;
      os << "object " << k << " (" << (o.name.empty() ? "unnamed" : o.name) << "): " << field
         << " = " << value << " outside " << allowed;
      throw std::invalid_argument(os.str());
    };
    for (int c = 0; c < 3; ++c) {
      if (!std::isfinite(o.state.r_eci_m[c])) fail("r_eci_m", o.state.r_eci_m[c], "finite values");
      if (!std::isfinite(o.state.v_eci_mps[c]))
        fail("v_eci_mps", o.state.v_eci_mps[c], "finite values");
    }
    if (!(o.size_m >= 0.0) || !std::isfinite(o.size_m)) fail("size_m", o.size_m, "[0, inf)");
    if (!(o.pos_error_m >= 0.0) || !std::isfinite(o.pos_error_m))
      fail("pos_error_m", o.pos_error_m, "[0, inf)");
    if (!(o.state.r_eci_m.norm() > 0.0)) fail("r_eci_m", 0.0, "a non-zero vector");
    const double r = o.state.r_eci_m.norm();
    const double inv_a = 2.0 / r - o.state.v_eci_mps.squaredNorm() / earth.mu_m3ps2;
    const Vec3 h = o.state.r_eci_m.cross(o.state.v_eci_mps);
    const double e =
        (o.state.v_eci_mps.cross(h) / earth.mu_m3ps2 - o.state.r_eci_m / r).norm();
    if (!(inv_a > 0.0) || !(e < 1.0)) fail("e", e, "[0, 1) (bound orbit)");
    const double rp = (1.0 / inv_a) * (1.0 - e);
    if (!(rp > earth.re_m)) fail("perigee_radius_m", rp, "(re_m, inf): perigee inside the Earth");
  }
}

}  // namespace evade::conjunction
