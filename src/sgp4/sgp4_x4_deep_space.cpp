// The four-lane lunar-solar periodics of SDP4 (deep_space.cpp's dpper over AVX2 lanes, for
// propagate_x4's deep-space lanes, sgp4_x4.cpp).
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
// Deep-space lanes (propagate_deep_x4, SDP4) take their secular and resonance terms from the
// scalar code lane by lane (Sgp4Propagator::mean_min), then the lunar-solar periodics of
// deep_space.cpp (periodics_x4, with libmvec's sine and cosine; Lyddane's arctangent lane by
// lane).
#include "evade/sgp4/internal/sgp4_x4_lanes.hpp"

#ifdef EVADE_SGP4_X4

#include <cmath>

namespace evade::sgp4::internal {

namespace {

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

}  // namespace

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

}  // namespace evade::sgp4::internal

#endif  // EVADE_SGP4_X4
