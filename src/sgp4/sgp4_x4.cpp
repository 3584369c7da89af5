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
//  - nothing else is fused: the file is compiled with -ffp-contract=off (CMakeLists.txt),
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
// every call.
#include "evade/sgp4/sgp4.hpp"

#include <cmath>
#include <cstddef>
#include <new>

#if defined(__x86_64__) && defined(EVADE_HAVE_LIBMVEC)
#include <immintrin.h>
#define EVADE_SGP4_X4 1
#endif

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

// glibc's libmvec sine and cosine of four doubles (its x86-64 vector ABI names, AVX2 'd'
// variant: at most 4 ulp).
extern "C" {
__attribute__((target("avx2,fma"))) __m256d sin_x4(__m256d x) __asm__("_ZGVdN4v_sin");
__attribute__((target("avx2,fma"))) __m256d cos_x4(__m256d x) __asm__("_ZGVdN4v_cos");
}

namespace {

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

__attribute__((target("avx2,fma"))) Perturbed secular_x4(const Lanes& L, V t, V* bad) noexcept {
  const V xmdf = add(ld(L.mo), mul(ld(L.mdot), t));
  const V argpdf = add(ld(L.argpo), mul(ld(L.argpdot), t));
  const V nodedf = add(ld(L.nodeo), mul(ld(L.nodedot), t));
  const V t2 = mul(t, t);
  V mm = xmdf, argpm = argpdf;
  const V nodem = add(nodedf, mul(ld(L.nodecf), t2));
  V tempa = sub(splat(1.0), mul(ld(L.cc1), t));
  V tempe = mul(ld(L.bstar_cc4), t);
  V templ = mul(ld(L.t2cof), t2);
  const V simp = ld(L.simp);
  if (_mm256_movemask_pd(simp) != 0xF) {  // some lane has the higher-order terms
    const V delomg = mul(ld(L.omgcof), t);
    const V delmtemp = add(splat(1.0), mul(ld(L.eta), cos_x4(xmdf)));
    const V delm = mul(ld(L.xmcof), sub(mul(mul(delmtemp, delmtemp), delmtemp), ld(L.delmo)));
    const V temp = add(delomg, delm);
    const V mm_h = add(xmdf, temp);
    const V t3 = mul(t2, t), t4 = mul(t3, t);
    const V tempa_h = sub(sub(sub(tempa, mul(ld(L.d2), t2)), mul(ld(L.d3), t3)), mul(ld(L.d4), t4));
    const V tempe_h = add(tempe, mul(ld(L.bstar_cc5), sub(sin_x4(mm_h), ld(L.sinmao))));
    const V templ_h = add(add(templ, mul(ld(L.t3cof), t3)),
                          mul(t4, add(ld(L.t4cof), mul(t, ld(L.t5cof)))));
    mm = pick(simp, mm, mm_h);
    argpm = pick(simp, argpm, sub(argpdf, temp));
    tempa = pick(simp, tempa, tempa_h);
    tempe = pick(simp, tempe, tempe_h);
    templ = pick(simp, templ, templ_h);
  }
  Perturbed q;
  q.am = mul(mul(ld(L.am_near), tempa), tempa);
  q.nm = dvd(ld(L.xke), mul(q.am, vsqrt(q.am)));
  V em = sub(ld(L.ecco), tempe);
  *bad = vor(ge(em, splat(1.0)), lt(em, splat(-0.001)));
  em = pick(lt(em, splat(1.0e-6)), splat(1.0e-6), em);
  const V mm0 = add(mm, mul(ld(L.no_unkozai), templ));
  const V xlm = mod_two_pi(add(add(mm0, argpm), nodem));
  q.nodep = mod_two_pi(nodem);
  q.argpp = mod_two_pi(argpm);
  q.mp = mod_two_pi(sub(sub(xlm, q.argpp), q.nodep));
  q.ep = em;
  return q;
}

// solve_kepler of sgp4.cpp, lane by lane: a lane stops changing once its step is below
// 1e-12 (or after 10 iterations), as the scalar loop exits.
__attribute__((target("avx2,fma"))) SC kepler_x4(V u, V axnl, V aynl) noexcept {
  V eo1 = u, tem5 = splat(9999.9), step = splat(0.0);
  SC sc{sin_x4(u), cos_x4(u)};
  V active = ge(vabs(tem5), splat(1.0e-12));
  for (int ktr = 1; ktr <= 10 && any(active); ++ktr) {
    if (ktr > 1) {
      SC next = rotate(sc, step);
      const V big = vand(active, gt(vabs(step), splat(1e-2)));
      if (any(big)) next = {pick(big, sin_x4(eo1), next.s), pick(big, cos_x4(eo1), next.c)};
      sc = {pick(active, next.s, sc.s), pick(active, next.c, sc.c)};
    }
    V t5 = sub(sub(splat(1.0), mul(sc.c, axnl)), mul(sc.s, aynl));
    t5 = dvd(sub(add(sub(u, mul(aynl, sc.c)), mul(axnl, sc.s)), eo1), t5);
    const V clamp = ge(vabs(t5), splat(0.95));
    t5 = pick(clamp, pick(gt(t5, splat(0.0)), splat(0.95), splat(-0.95)), t5);
    step = pick(active, t5, step);
    eo1 = pick(active, add(eo1, t5), eo1);
    tem5 = pick(active, t5, tem5);
    active = vand(active, ge(vabs(tem5), splat(1.0e-12)));
  }
  return sc;
}

// position_velocity of sgp4.cpp (near-Earth: the epoch inclination's coefficients).
__attribute__((target("avx2,fma"), always_inline)) inline void position_velocity_x4(
    const Lanes& L, const ShortLanes& S, const Perturbed& q, V bad, Out* o) noexcept {
  const V ep = q.ep, am = q.am;
  const V axnl = mul(ep, cos_x4(q.argpp));
  V temp = dvd(splat(1.0), mul(am, sub(splat(1.0), mul(ep, ep))));
  const V aynl = add(mul(ep, sin_x4(q.argpp)), mul(temp, ld(S.aycof)));
  const V xl = add(add(add(q.mp, q.argpp), q.nodep), mul(mul(temp, ld(S.xlcof)), axnl));
  const SC ks = kepler_x4(mod_two_pi(sub(xl, q.nodep)), axnl, aynl);
  const V ecose = add(mul(axnl, ks.c), mul(aynl, ks.s));
  const V esine = sub(mul(axnl, ks.s), mul(aynl, ks.c));
  const V el2 = add(mul(axnl, axnl), mul(aynl, aynl));
  const V pl = mul(am, sub(splat(1.0), el2));
  bad = vor(bad, vor(lt(pl, splat(0.0)), lt(pl, splat(1.0))));  // pl < 1: corrections may be large
  const V rl = mul(am, sub(splat(1.0), ecose));
  const V rdotl = dvd(mul(vsqrt(am), esine), rl);
  const V rvdotl = dvd(vsqrt(pl), rl);
  const V betal = vsqrt(sub(splat(1.0), el2));
  temp = dvd(esine, add(splat(1.0), betal));
  const V amrl = dvd(am, rl);
  const V sinu = mul(amrl, sub(sub(ks.s, aynl), mul(axnl, temp)));
  const V cosu = mul(amrl, add(sub(ks.c, axnl), mul(aynl, temp)));
  const V sin2u = mul(add(cosu, cosu), sinu);
  const V cos2u = sub(splat(1.0), mul(mul(splat(2.0), sinu), sinu));
  temp = dvd(splat(1.0), pl);
  const V temp1 = mul(mul(splat(0.5), ld(L.j2)), temp);
  const V temp2 = mul(temp1, temp);
  const V con41 = ld(S.con41), x1mth2 = ld(S.x1mth2), sinip = ld(S.sinip), cosip = ld(S.cosip);
  const V mrt = add(mul(rl, sub(splat(1.0), mul(mul(mul(splat(1.5), temp2), betal), con41))),
                    mul(mul(mul(splat(0.5), temp1), x1mth2), cos2u));
  const V dsu = mul(mul(mul(splat(-0.25), temp2), ld(S.x7thm1)), sin2u);
  const V norm = vsqrt(add(mul(sinu, sinu), mul(cosu, cosu)));
  const SC su = rotate({dvd(sinu, norm), dvd(cosu, norm)}, dsu);
  const V dinc = mul(mul(mul(mul(splat(1.5), temp2), cosip), sinip), cos2u);
  const SC inc = rotate({sinip, cosip}, dinc);
  bad = vor(bad, vor(gt(vabs(dsu), splat(1e-2)), gt(vabs(dinc), splat(1e-2))));
  const V xnode = add(q.nodep, mul(mul(mul(splat(1.5), temp2), cosip), sin2u));
  const V xke = ld(L.xke);
  const V mvt = sub(rdotl, dvd(mul(mul(mul(q.nm, temp1), x1mth2), sin2u), xke));
  const V rvdot = add(rvdotl, dvd(mul(mul(q.nm, temp1), add(mul(x1mth2, cos2u), mul(splat(1.5), con41))), xke));
  const V snod = sin_x4(xnode), cnod = cos_x4(xnode);
  const V xmx = mul(_mm256_xor_pd(snod, splat(-0.0)), inc.c), xmy = mul(cnod, inc.c);
  const V uv[3] = {add(mul(xmx, su.s), mul(cnod, su.c)), add(mul(xmy, su.s), mul(snod, su.c)),
                   mul(inc.s, su.s)};
  const V vv[3] = {sub(mul(xmx, su.c), mul(cnod, su.s)), sub(mul(xmy, su.c), mul(snod, su.s)),
                   mul(inc.s, su.c)};
  const V vkmpersec = dvd(mul(ld(L.radius_km), xke), splat(60.0));
  const V mr_km = mul(mrt, ld(L.radius_km));
  for (int a = 0; a < 3; ++a) {
    _mm256_storeu_pd(o->r[a], mul(mul(mr_km, uv[a]), splat(1000.0)));
    _mm256_storeu_pd(o->v[a], mul(mul(add(mul(mvt, uv[a]), mul(rvdot, vv[a])), vkmpersec), splat(1000.0)));
  }
  bad = vor(bad, lt(mrt, splat(1.0)));  // decayed
  _mm256_storeu_pd(o->bad, bad);
}

__attribute__((target("avx2,fma"))) void propagate_lanes(const Lanes& L, const double tsince_min[4],
                                                     Out* o) noexcept {
  V bad;
  const Perturbed q = secular_x4(L, _mm256_loadu_pd(tsince_min), &bad);
  position_velocity_x4(L, L.s, q, bad, o);
}

// Deep-space lanes at one instant: the elements dpper starts from, the semi-major axis and
// mean motion of each lane from Sgp4Propagator::mean_min; bad all-ones bits where mean_min
// reported an error.
struct DeepIn {
  double am[4], nm[4], ep[4], inclp[4], nodep[4], argpp[4], mp[4], bad[4];
};

// c2 f2 + c3 f3.
EVADE_AVX2 V sum2(V c2, V f2, V c3, V f3) { return add(mul(c2, f2), mul(c3, f3)); }

// One body's (sun's or moon's) f2, f3 and sin zf at t (dpper): zm = zm0 + n t,
// zf = zm + 2 e sin zm.
struct BodyTerms {
  V f2, f3, sinzf;
};

EVADE_AVX2 BodyTerms body_terms(V zm0, double n, double e, V t) {
  const V zm = add(zm0, mul(splat(n), t));
  const V zf = add(zm, mul(splat(2.0 * e), sin_x4(zm)));
  const V sinzf = sin_x4(zf);
  return {sub(mul(mul(splat(0.5), sinzf), sinzf), splat(0.25)),
          mul(mul(splat(-0.5), sinzf), cos_x4(zf)), sinzf};
}

// The perturbed elements of the deep-space lanes, and the sine and cosine of their perturbed
// inclination; bad all-ones bits where the lane goes back to propagate_min.
struct DeepOut {
  double ep[4], nodep[4], argpp[4], mp[4], sinip[4], cosip[4], bad[4];
};

// deep_space_periodics (deep_space.cpp, dpper) over four lanes in its order of operations,
// both of its branches (inclination >= 0.2 rad, else Lyddane's) computed and the lane's one
// kept, then propagate_min's negative-inclination turn and eccentricity check (bad where the
// eccentricity leaves [0, 1]).
__attribute__((target("avx2,fma"))) void periodics_x4(const DeepCoef& c, const DeepIn& d,
                                                  const double t_min[4], DeepOut* o) noexcept {
  const V t = ld(t_min);
  constexpr double kPi = 3.14159265358979323846, kTwoPi = 2.0 * kPi;  // deep_space.cpp's
  const BodyTerms s = body_terms(ld(c.zmos), 1.19459e-5, 0.01675, t);    // kZns, kZes
  const BodyTerms l = body_terms(ld(c.zmol), 1.5835218e-4, 0.05490, t);  // kZnl, kZel
  const V pe = add(sum2(ld(c.se2), s.f2, ld(c.se3), s.f3), sum2(ld(c.ee2), l.f2, ld(c.e3), l.f3));
  const V pinc = add(sum2(ld(c.si2), s.f2, ld(c.si3), s.f3), sum2(ld(c.xi2), l.f2, ld(c.xi3), l.f3));
  const V pl = add(add(sum2(ld(c.sl2), s.f2, ld(c.sl3), s.f3), mul(ld(c.sl4), s.sinzf)),
                   add(sum2(ld(c.xl2), l.f2, ld(c.xl3), l.f3), mul(ld(c.xl4), l.sinzf)));
  const V pgh = add(add(sum2(ld(c.sgh2), s.f2, ld(c.sgh3), s.f3), mul(ld(c.sgh4), s.sinzf)),
                    add(sum2(ld(c.xgh2), l.f2, ld(c.xgh3), l.f3), mul(ld(c.xgh4), l.sinzf)));
  const V ph = add(sum2(ld(c.sh2), s.f2, ld(c.sh3), s.f3), sum2(ld(c.xh2), l.f2, ld(c.xh3), l.f3));
  Perturbed q;
  const V inclp = add(ld(d.inclp), pinc);
  q.ep = add(ld(d.ep), pe);
  const V sinip = sin_x4(inclp), cosip = cos_x4(inclp);
  const V nodep0 = ld(d.nodep), argpp0 = ld(d.argpp), mp0 = ld(d.mp);
  // Inclination >= 0.2 rad.
  const V ph_hi = dvd(ph, sinip);
  const V argpp_hi = add(argpp0, sub(pgh, mul(cosip, ph_hi)));
  const V nodep_hi = add(nodep0, ph_hi);
  // Lyddane's modification below it.
  const V sinop = sin_x4(nodep0), cosop = cos_x4(nodep0);
  const V alfdp = add(mul(sinip, sinop), add(mul(ph, cosop), mul(mul(pinc, cosip), sinop)));
  const V betdp = add(mul(sinip, cosop), add(mul(_mm256_xor_pd(ph, splat(-0.0)), sinop),
                                             mul(mul(pinc, cosip), cosop)));
  const V afspc = gt(ld(c.afspc), splat(0.5));  // all-ones bits (vand keeps what it selects)
  V node = mod_two_pi(nodep0);
  node = add(node, vand(vand(afspc, lt(node, splat(0.0))), splat(kTwoPi)));
  const V xls = add(add(add(add(mp0, argpp0), pl), pgh), mul(sub(cosip, mul(pinc, sinip)), node));
  // Lyddane's node by std::atan2 lane by lane, as deep_space_periodics (libmvec's two-argument
  // atan2 came out wrong through Clang's -O0 calls), where some lane takes that branch.
  const V hi = ge(inclp, splat(0.2));
  V nodel = nodep_hi;
  if (_mm256_movemask_pd(hi) != 0xF) {
    alignas(32) double y[4], x[4], a[4];
    _mm256_store_pd(y, alfdp);
    _mm256_store_pd(x, betdp);
    for (int k = 0; k < 4; ++k) a[k] = std::atan2(y[k], x[k]);
    nodel = _mm256_load_pd(a);
  }
  nodel = add(nodel, vand(vand(afspc, lt(nodel, splat(0.0))), splat(kTwoPi)));
  const V wrap = gt(vabs(sub(node, nodel)), splat(kPi));
  nodel = add(nodel, vand(wrap, pick(lt(nodel, node), splat(kTwoPi), splat(-kTwoPi))));
  q.mp = add(mp0, pl);
  const V argpp_lo = sub(sub(xls, q.mp), mul(cosip, nodel));
  V incl = inclp;
  q.nodep = pick(hi, nodep_hi, nodel);
  q.argpp = pick(hi, argpp_hi, argpp_lo);
  // A negative inclination: turned, the node and perigee moved by pi (propagate_min).
  const V neg = lt(incl, splat(0.0));
  incl = pick(neg, _mm256_xor_pd(incl, splat(-0.0)), incl);
  q.nodep = pick(neg, add(q.nodep, splat(kPi)), q.nodep);
  q.argpp = pick(neg, sub(q.argpp, splat(kPi)), q.argpp);
  _mm256_storeu_pd(o->bad, vor(ld(d.bad), vor(lt(q.ep, splat(0.0)), gt(q.ep, splat(1.0)))));
  _mm256_storeu_pd(o->ep, q.ep);
  _mm256_storeu_pd(o->nodep, q.nodep);
  _mm256_storeu_pd(o->argpp, q.argpp);
  _mm256_storeu_pd(o->mp, q.mp);
  _mm256_storeu_pd(o->sinip, sin_x4(incl));
  _mm256_storeu_pd(o->cosip, cos_x4(incl));
}

// position_velocity_x4 of the deep-space lanes (S: their perturbed inclination's coefficients).
__attribute__((target("avx2,fma"))) void deep_lanes(const Lanes& L, const ShortLanes& S, const DeepIn& d,
                                                const DeepOut& e, Out* o) noexcept {
  Perturbed q;
  q.am = ld(d.am);
  q.nm = ld(d.nm);
  q.ep = ld(e.ep);
  q.nodep = ld(e.nodep);
  q.argpp = ld(e.argpp);
  q.mp = ld(e.mp);
  position_velocity_x4(L, S, q, ld(e.bad), o);
}

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
