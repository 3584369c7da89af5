// Near-Earth SGP4 for four element sets at once (sgp4.hpp, propagate_near_x4): the formulas
// of Sgp4Propagator::propagate_min (Vallado, Crawford, Hujsak & Kelso 2006, "Revisiting
// Spacetrack Report #3", the near-Earth branch of sgp4: secular gravity and drag, long-period
// periodics, Kepler's equation in the Lyddane variables, short-period J2 terms, the unit
// vectors U and V), written once more over AVX2 lanes of four doubles, in the same order of
// operations, so that each lane rounds as the scalar code does except in three places:
//  - sine and cosine are glibc's vector ones (libmvec, at most 4 ulp; the scalar ones are
//    within 1 ulp);
//  - x mod 2 pi is x - q 2 pi with q = trunc(x / 2 pi), by one fused multiply-add: exact,
//    as fmod is, since the remainder is a multiple of ulp(2 pi) below 2^53 of them (where
//    x / 2 pi rounds across an integer, q is off by one and the remainder is the same
//    angle less or more 2 pi);
//  - nothing else is fused: the files are compiled with -ffp-contract=off (CMakeLists.txt),
//    so every other product is rounded before its sum, as in the scalar build.
// Kepler's iteration runs per lane: a lane stops updating when its step is below 1e-12, as
// the scalar loop exits. The differences stay far inside kSgp4X4PositionError_m (1 mm;
// docs/VALIDATION.md, test/sgp4/sgp4_x4_test.cpp). Anything unusual (an error or decay, a
// short-period correction beyond the rotation range) sends the lane back to propagate_min.
// Deep-space lanes (propagate_deep_x4, SDP4) take their secular and resonance terms from the
// scalar code lane by lane (Sgp4Propagator::mean_min), then the lunar-solar periodics of
// deep_space.cpp (periodics_x4, with libmvec's sine and cosine; Lyddane's arctangent lane by
// lane) and the rest
// (position_velocity_x4) in the lanes. Sgp4X4Lanes gathers four element sets' constants once
// for many instants (propagate_x4); propagate_near_x4 and propagate_deep_x4 gather them at
// every call. This file gathers the constants and dispatches; the lanes' kernels are
// sgp4_x4_near_earth.cpp (secular terms to position and velocity) and sgp4_x4_deep_space.cpp
// (the lunar-solar periodics), their shared types internal/sgp4_x4_lanes.hpp.
#include "evade/sgp4/sgp4.hpp"

#include <cmath>
#include <cstddef>
#include <new>

#include "evade/sgp4/internal/sgp4_x4_lanes.hpp"

namespace evade::sgp4 {

namespace {

// One lane after the other (no AVX2, or the vector library is absent).
void propagate_scalar(const Sgp4Propagator* const p[4], const double tsince_min[4],
                           double r_teme_m[4][3], double v_teme_mps[4][3], bool ok[4]) noexcept {
  for (int k = 0; k < 4; ++k) {
    const Sgp4State s = p[k]->propagate_min(tsince_min[k]);
    ok[k] = s.error == Sgp4Error::kNone;
    for (int a = 0; a < 3; ++a) {
      r_teme_m[k][a] = s.r_teme_m[a];
      v_teme_mps[k][a] = s.v_teme_mps[a];
    }
  }
}

}  // namespace

#ifdef EVADE_SGP4_X4

namespace {

using internal::DeepCoef;
using internal::DeepIn;
using internal::DeepOut;
using internal::Lanes;
using internal::Out;
using internal::Prepared;
using internal::ShortLanes;
using internal::deep_lanes;
using internal::periodics_x4;
using internal::propagate_lanes;

bool avx2_present() noexcept {
  __builtin_cpu_init();
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
}

}  // namespace

#endif  // EVADE_SGP4_X4

bool sgp4_x4_vectorized() noexcept {
#ifdef EVADE_SGP4_X4
  static const bool yes = avx2_present();
  return yes;
#else
  return false;
#endif
}

Sgp4X4Lanes::Sgp4X4Lanes(const Sgp4Propagator* const p[4]) noexcept : deep_(p[0]->deep_space()) {
#ifdef EVADE_SGP4_X4
  auto* prepared = new (storage_) Prepared;  // trivially destructible: nothing to undo
  Lanes& L = prepared->L;
  DeepCoef& D = prepared->D;
  for (int k = 0; k < 4; ++k) {
    const Sgp4Propagator& s = *p[k];
    L.xke[k] = s.k_.xke_per_min;
    L.j2[k] = s.k_.j2;
    L.radius_km[k] = s.k_.radius_km;
    if (deep_) {
      const LunarSolarPeriodics& c = s.ds_.periodics;
      const double* from[] = {&c.e3,   &c.ee2,  &c.se2,  &c.se3,  &c.sgh2, &c.sgh3, &c.sgh4,
                              &c.sh2,  &c.sh3,  &c.si2,  &c.si3,  &c.sl2,  &c.sl3,  &c.sl4,
                              &c.xgh2, &c.xgh3, &c.xgh4, &c.xh2,  &c.xh3,  &c.xi2,  &c.xi3,
                              &c.xl2,  &c.xl3,  &c.xl4,  &c.zmol, &c.zmos};
      double* to[] = {D.e3,   D.ee2,  D.se2,  D.se3,  D.sgh2, D.sgh3, D.sgh4, D.sh2,  D.sh3,
                      D.si2,  D.si3,  D.sl2,  D.sl3,  D.sl4,  D.xgh2, D.xgh3, D.xgh4, D.xh2,
                      D.xh3,  D.xi2,  D.xi3,  D.xl2,  D.xl3,  D.xl4,  D.zmol, D.zmos};
      for (std::size_t m = 0; m < sizeof(from) / sizeof(from[0]); ++m) to[m][k] = *from[m];
      D.afspc[k] = s.mode_ == OperationMode::kAfspc ? 1.0 : 0.0;
      continue;
    }
    L.mo[k] = s.el_.mo_rad;
    L.mdot[k] = s.ep_.mdot;
    L.argpo[k] = s.el_.argpo_rad;
    L.argpdot[k] = s.ep_.argpdot;
    L.nodeo[k] = s.el_.nodeo_rad;
    L.nodedot[k] = s.ep_.nodedot;
    L.nodecf[k] = s.nodecf_;
    L.cc1[k] = s.cc1_;
    L.bstar_cc4[k] = s.el_.bstar_per_er * s.cc4_;
    L.bstar_cc5[k] = s.el_.bstar_per_er * s.cc5_;
    L.t2cof[k] = s.t2cof_;
    L.t3cof[k] = s.t3cof_;
    L.t4cof[k] = s.t4cof_;
    L.t5cof[k] = s.t5cof_;
    L.omgcof[k] = s.omgcof_;
    L.eta[k] = s.eta_;
    L.xmcof[k] = s.xmcof_;
    L.delmo[k] = s.delmo_;
    L.d2[k] = s.d2_;
    L.d3[k] = s.d3_;
    L.d4[k] = s.d4_;
    L.sinmao[k] = s.sinmao_;
    L.simp[k] = s.isimp_ ? -std::nan("") : 0.0;  // any all-ones-sign pattern: blend mask
    L.no_unkozai[k] = s.no_unkozai_;
    L.ecco[k] = s.el_.ecco;
    L.am_near[k] = s.am_near_;
    L.s.sinip[k] = s.sin_inclo_;
    L.s.cosip[k] = s.cos_inclo_;
    L.s.con41[k] = s.near_.con41;
    L.s.x1mth2[k] = s.near_.x1mth2;
    L.s.x7thm1[k] = s.near_.x7thm1;
    L.s.aycof[k] = s.near_.aycof;
    L.s.xlcof[k] = s.near_.xlcof;
  }
#else
  (void)storage_;
#endif
}

void propagate_x4(const Sgp4X4Lanes& lanes, const Sgp4Propagator* const p[4],
                  const double tsince_min[4], double r_teme_m[4][3], double v_teme_mps[4][3],
                  bool ok[4]) noexcept {
#ifdef EVADE_SGP4_X4
  if (sgp4_x4_vectorized()) {
    // The deep-space lanes: mean_min lane by lane (a lane it fails gets harmless elements and
    // is flagged; propagate_min then reports its error), the lunar-solar periodics four at a
    // time, the coefficients short_period makes of the perturbed inclination lane by lane,
    // then position_velocity_x4.
    const auto deep_step = [&](const Prepared& P, Out* o) {
      DeepIn d;
      for (int k = 0; k < 4; ++k) {
        PerturbedElements e;
        double am = 0.0, nm = 0.0;
        const bool good = p[k]->mean_min(tsince_min[k], e, am, nm) == Sgp4Error::kNone;
        if (!good) e = PerturbedElements{0.1, 0.5, 0.0, 0.0, 0.0};
        d.am[k] = good ? am : 2.0;
        d.nm[k] = good ? nm : P.L.xke[k] / (2.0 * std::sqrt(2.0));
        d.ep[k] = e.ep;
        d.inclp[k] = e.inclp;
        d.nodep[k] = e.nodep;
        d.argpp[k] = e.argpp;
        d.mp[k] = e.mp;
        d.bad[k] = good ? 0.0 : -std::nan("");  // any all-ones-sign pattern: a mask lane
      }
      DeepOut e;
      periodics_x4(P.D, d, tsince_min, &e);
      ShortLanes S;
      for (int k = 0; k < 4; ++k) {
        const Sgp4Propagator::Short c = p[k]->short_period(e.sinip[k], e.cosip[k]);
        S.sinip[k] = e.sinip[k];
        S.cosip[k] = e.cosip[k];
        S.con41[k] = c.con41;
        S.x1mth2[k] = c.x1mth2;
        S.x7thm1[k] = c.x7thm1;
        S.aycof[k] = c.aycof;
        S.xlcof[k] = c.xlcof;
      }
      deep_lanes(P.L, S, d, e, o);
    };
    const Prepared& P = *std::launder(reinterpret_cast<const Prepared*>(lanes.storage_));
    Out o;
    if (lanes.deep()) {
      deep_step(P, &o);
    } else {
      propagate_lanes(P.L, tsince_min, &o);
    }
    for (int k = 0; k < 4; ++k) {
      ok[k] = o.bad[k] == 0.0;  // the mask's lanes are all-ones bits (a NaN) or zero
      for (int a = 0; a < 3; ++a) {
        r_teme_m[k][a] = o.r[a][k];
        v_teme_mps[k][a] = o.v[a][k];
      }
    }
    return;
  }
#endif
  (void)lanes;
  propagate_scalar(p, tsince_min, r_teme_m, v_teme_mps, ok);
}

void propagate_near_x4(const Sgp4Propagator* const p[4], const double tsince_min[4],
                       double r_teme_m[4][3], double v_teme_mps[4][3], bool ok[4]) noexcept {
  propagate_x4(Sgp4X4Lanes(p), p, tsince_min, r_teme_m, v_teme_mps, ok);
}

void propagate_deep_x4(const Sgp4Propagator* const p[4], const double tsince_min[4],
                       double r_teme_m[4][3], double v_teme_mps[4][3], bool ok[4]) noexcept {
  propagate_x4(Sgp4X4Lanes(p), p, tsince_min, r_teme_m, v_teme_mps, ok);
}

}  // namespace evade::sgp4
