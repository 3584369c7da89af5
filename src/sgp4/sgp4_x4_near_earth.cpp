// The four-lane kernel of near-Earth SGP4 (sgp4_x4.cpp, propagate_x4): secular gravity and
// drag, Kepler's equation lane by lane, the short-period terms, position and velocity.
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
#include "evade/sgp4/internal/sgp4_x4_lanes.hpp"

#ifdef EVADE_SGP4_X4

namespace evade::sgp4::internal {

namespace {

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

}  // namespace

__attribute__((target("avx2,fma"))) void propagate_lanes(const Lanes& L, const double tsince_min[4],
                                                     Out* o) noexcept {
  V bad;
  const Perturbed q = secular_x4(L, _mm256_loadu_pd(tsince_min), &bad);
  position_velocity_x4(L, L.s, q, bad, o);
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

}  // namespace evade::sgp4::internal

#endif  // EVADE_SGP4_X4
