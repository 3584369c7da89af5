// Internal (not installed): what the four-lane SGP4 files share (src/sgp4/sgp4_x4.cpp,
// sgp4_x4_near_earth.cpp, sgp4_x4_deep_space.cpp): libmvec's vector sine and cosine, the AVX2
// lane helpers, the per-lane constants Sgp4X4Lanes holds and the kernels over them.
#pragma once

#include "evade/sgp4/sgp4.hpp"

#if defined(__x86_64__) && defined(EVADE_HAVE_LIBMVEC)
#include <immintrin.h>
#define EVADE_SGP4_X4 1
#endif

#ifdef EVADE_SGP4_X4

namespace evade::sgp4 {

// glibc's libmvec sine and cosine of four doubles (its x86-64 vector ABI names, AVX2 'd'
// variant: at most 4 ulp).
extern "C" {
__attribute__((target("avx2,fma"))) __m256d sin_x4(__m256d x) __asm__("_ZGVdN4v_sin");
__attribute__((target("avx2,fma"))) __m256d cos_x4(__m256d x) __asm__("_ZGVdN4v_cos");
}

}  // namespace evade::sgp4

namespace evade::sgp4::internal {

#define EVADE_AVX2 __attribute__((target("avx2,fma"), always_inline)) inline

using V = __m256d;

EVADE_AVX2 V splat(double x) { return _mm256_set1_pd(x); }
EVADE_AVX2 V add(V a, V b) { return _mm256_add_pd(a, b); }
EVADE_AVX2 V sub(V a, V b) { return _mm256_sub_pd(a, b); }
EVADE_AVX2 V mul(V a, V b) { return _mm256_mul_pd(a, b); }
EVADE_AVX2 V dvd(V a, V b) { return _mm256_div_pd(a, b); }
EVADE_AVX2 V vsqrt(V a) { return _mm256_sqrt_pd(a); }
EVADE_AVX2 V vabs(V a) { return _mm256_andnot_pd(_mm256_set1_pd(-0.0), a); }
EVADE_AVX2 V ge(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GE_OQ); }
EVADE_AVX2 V lt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_LT_OQ); }
EVADE_AVX2 V gt(V a, V b) { return _mm256_cmp_pd(a, b, _CMP_GT_OQ); }
EVADE_AVX2 V vand(V a, V b) { return _mm256_and_pd(a, b); }
EVADE_AVX2 V vor(V a, V b) { return _mm256_or_pd(a, b); }
EVADE_AVX2 V pick(V mask, V yes, V no) { return _mm256_blendv_pd(no, yes, mask); }
EVADE_AVX2 bool any(V mask) { return _mm256_movemask_pd(mask) != 0; }

// x - trunc(x / 2 pi) 2 pi with one rounding of the exact value: x mod 2 pi with the sign
// of x, as fmod.
EVADE_AVX2 V mod_two_pi(V x) {
  constexpr double kTwoPi = 2.0 * 3.14159265358979323846;  // sgp4.cpp's kTwoPi
  const V q = _mm256_round_pd(dvd(x, splat(kTwoPi)), _MM_FROUND_TO_ZERO | _MM_FROUND_NO_EXC);
  return _mm256_fnmadd_pd(q, splat(kTwoPi), x);
}

struct SC {
  V s, c;
};

// sgp4.cpp's rotate: sin and cos of a + d from those of a, Taylor series of sin d and cos d.
EVADE_AVX2 SC rotate(SC a, V d) {
  const V d2 = mul(d, d);
  const V sd = mul(d, add(splat(1.0), mul(d2, add(splat(-1.0 / 6.0),
                                             mul(d2, add(splat(1.0 / 120.0), mul(d2, splat(-1.0 / 5040.0))))))));
  const V cd = add(splat(1.0),
                   mul(d2, add(splat(-0.5),
                               mul(d2, add(splat(1.0 / 24.0),
                                           mul(d2, add(splat(-1.0 / 720.0), mul(d2, splat(1.0 / 40320.0)))))))));
  return {add(mul(a.s, cd), mul(a.c, sd)), sub(mul(a.c, cd), mul(a.s, sd))};
}

// The inclination's sine and cosine and the short-period coefficients of each lane (the
// epoch inclination's for near-Earth lanes, the perturbed one's for deep-space lanes).
struct ShortLanes {
  double sinip[4], cosip[4], con41[4], x1mth2[4], x7thm1[4], aycof[4], xlcof[4];
};

// The per-lane constants of Sgp4Propagator the near-Earth formulas read, lane k in [k]
// (deep-space lanes: xke, j2 and radius_km only).
struct Lanes {
  double mo[4], mdot[4], argpo[4], argpdot[4], nodeo[4], nodedot[4], nodecf[4];
  double cc1[4], bstar_cc4[4], bstar_cc5[4], t2cof[4], t3cof[4], t4cof[4], t5cof[4];
  double omgcof[4], eta[4], xmcof[4], delmo[4], d2[4], d3[4], d4[4], sinmao[4];
  double simp[4];  // all-ones bits where isimp (no higher-order drag terms), else 0
  double no_unkozai[4], ecco[4], am_near[4], xke[4], j2[4], radius_km[4];
  ShortLanes s;
};

// The lunar-solar coefficients of deep-space lanes (deep_space.hpp's LunarSolarPeriodics)
// and their operation mode.
struct DeepCoef {
  double e3[4], ee2[4], se2[4], se3[4], sgh2[4], sgh3[4], sgh4[4], sh2[4], sh3[4];
  double si2[4], si3[4], sl2[4], sl3[4], sl4[4], xgh2[4], xgh3[4], xgh4[4], xh2[4], xh3[4];
  double xi2[4], xi3[4], xl2[4], xl3[4], xl4[4], zmol[4], zmos[4];
  double afspc[4];  // 1 where the mode is kAfspc, else 0
};

// What Sgp4X4Lanes holds (sgp4.hpp): the constants of four lanes, gathered once.
struct Prepared {
  Lanes L;
  DeepCoef D;
};
static_assert(sizeof(Prepared) <= kSgp4X4LanesBytes, "Sgp4X4Lanes's storage is too small");
static_assert(alignof(Prepared) <= 32, "Sgp4X4Lanes's storage is aligned to 32 bytes");

struct Out {
  double r[3][4], v[3][4];
  double bad[4];  // nonzero where the lane must be redone by propagate_min
};

EVADE_AVX2 V ld(const double* x) { return _mm256_loadu_pd(x); }

// Secular gravity and drag and the perturbed elements (propagate_min up to
// position_velocity); *bad gets the lanes whose eccentricity leaves [-0.001, 1).
struct Perturbed {
  V am, nm, ep, nodep, argpp, mp;
};

// Deep-space lanes at one instant: the elements dpper starts from, the semi-major axis and
// mean motion of each lane from Sgp4Propagator::mean_min; bad all-ones bits where mean_min
// reported an error.
struct DeepIn {
  double am[4], nm[4], ep[4], inclp[4], nodep[4], argpp[4], mp[4], bad[4];
};

// The perturbed elements of the deep-space lanes, and the sine and cosine of their perturbed
// inclination; bad all-ones bits where the lane goes back to propagate_min.
struct DeepOut {
  double ep[4], nodep[4], argpp[4], mp[4], sinip[4], cosip[4], bad[4];
};

// The near-Earth lanes at four instants (sgp4_x4_near_earth.cpp).
__attribute__((target("avx2,fma"))) void propagate_lanes(const Lanes& L, const double tsince_min[4],
                                                     Out* o) noexcept;

// position_velocity_x4 of the deep-space lanes (S: their perturbed inclination's coefficients).
__attribute__((target("avx2,fma"))) void deep_lanes(const Lanes& L, const ShortLanes& S, const DeepIn& d,
                                                const DeepOut& e, Out* o) noexcept;

// deep_space_periodics (deep_space.cpp, dpper) over four lanes in its order of operations,
// both of its branches (inclination >= 0.2 rad, else Lyddane's) computed and the lane's one
// kept, then propagate_min's negative-inclination turn and eccentricity check (bad where the
// eccentricity leaves [0, 1]).
__attribute__((target("avx2,fma"))) void periodics_x4(const DeepCoef& c, const DeepIn& d,
                                                  const double t_min[4], DeepOut* o) noexcept;

}  // namespace evade::sgp4::internal

#endif  // EVADE_SGP4_X4
