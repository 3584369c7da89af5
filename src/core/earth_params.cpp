// Earth model parameter table (include/evade/core/earth_params.hpp). Ranges cover every body
// the papers use (paper 001: mu = 3.986005e14, Re = 6 371 110 m) with room for test models.
#include "evade/core/earth_params.hpp"

namespace evade {
namespace {

const Param<EarthModel> kRows[] = {
    EVADE_PARAM_REAL(EarthModel, mu_m3ps2, "m^3/s^2", 1e13, 1e15, false,
                     "gravitational parameter of the central body"),
    EVADE_PARAM_REAL(EarthModel, j2, "-", 0.0, 1e-2, false,
                     "second zonal harmonic (0 turns J2 off)"),
    EVADE_PARAM_REAL(EarthModel, re_m, "m", 1e6, 1e7, false,
                     "equatorial radius, the reference radius of J2"),
};

}  // namespace

ParamTable<EarthModel> earth_params() noexcept { return make_param_table(kRows); }

}  // namespace evade
