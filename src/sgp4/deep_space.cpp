// SDP4 deep-space terms: Vallado, Crawford, Hujsak & Kelso (2006), "Revisiting Spacetrack
// Report #3", AIAA 2006-6753 (dscom: lunar-solar geometry and periodic coefficients; dsinit:
// secular rates and resonance coefficients; dspace: resonance integration; dpper: periodics
// with the Lyddane choice), after Hoots & Roehrich (1980), STR#3. The numeric constants
// (zes, zel, c1ss, c1l, the Q and G resonance coefficients, fasx*, g**) are the theory's.
#include "evade/sgp4/deep_space.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

#include "evade/sgp4/sgp4.hpp"
#include "angles.hpp"

namespace evade::sgp4 {
namespace {

using detail::kPi;
using detail::kTwoPi;
constexpr double kZes = 0.01675;       // solar eccentricity
constexpr double kZel = 0.05490;       // lunar eccentricity
constexpr double kZns = 1.19459e-5;    // solar mean motion (rad/min)
constexpr double kZnl = 1.5835218e-4;  // lunar mean motion (rad/min)
constexpr double kRptim = 4.37526908801129966e-3;  // Earth rotation (rad/min)
constexpr double kStep = 720.0;        // resonance integration step (min)
constexpr double kStep2 = 259200.0;    // kStep^2 / 2

// The terms one perturbing body (Sun or Moon) contributes (dscom's loop body).
struct BodyTerms {
  double s1, s2, s3, s4, s5, s6, s7;
  double z1, z2, z3, z11, z12, z13, z21, z22, z23, z31, z32, z33;
};

struct BodyAxes {
  double cosg, sing, cosi, sini, cosh, sinh, cc;
};

struct OrbitAngles {
  double sinim, cosim, sinomm, cosomm, em, emsq, betasq, rtemsq, xnoi;
};

BodyTerms body_terms(const BodyAxes& b, const OrbitAngles& o) {
  BodyTerms t{};
  const double a1 = b.cosg * b.cosh + b.sing * b.cosi * b.sinh;
  const double a3 = -b.sing * b.cosh + b.cosg * b.cosi * b.sinh;
  const double a7 = -b.cosg * b.sinh + b.sing * b.cosi * b.cosh;
  const double a8 = b.sing * b.sini;
  const double a9 = b.sing * b.sinh + b.cosg * b.cosi * b.cosh;
  const double a10 = b.cosg * b.sini;
  const double a2 = o.cosim * a7 + o.sinim * a8;
  const double a4 = o.cosim * a9 + o.sinim * a10;
  const double a5 = -o.sinim * a7 + o.cosim * a8;
  const double a6 = -o.sinim * a9 + o.cosim * a10;
  const double x1 = a1 * o.cosomm + a2 * o.sinomm;
  const double x2 = a3 * o.cosomm + a4 * o.sinomm;
  const double x3 = -a1 * o.sinomm + a2 * o.cosomm;
  const double x4 = -a3 * o.sinomm + a4 * o.cosomm;
  const double x5 = a5 * o.sinomm, x6 = a6 * o.sinomm;
  const double x7 = a5 * o.cosomm, x8 = a6 * o.cosomm;
  const double emsq = o.emsq;
  t.z31 = 12.0 * x1 * x1 - 3.0 * x3 * x3;
  t.z32 = 24.0 * x1 * x2 - 6.0 * x3 * x4;
  t.z33 = 12.0 * x2 * x2 - 3.0 * x4 * x4;
  t.z1 = 3.0 * (a1 * a1 + a2 * a2) + t.z31 * emsq;
  t.z2 = 6.0 * (a1 * a3 + a2 * a4) + t.z32 * emsq;
  t.z3 = 3.0 * (a3 * a3 + a4 * a4) + t.z33 * emsq;
  t.z11 = -6.0 * a1 * a5 + emsq * (-24.0 * x1 * x7 - 6.0 * x3 * x5);
  t.z12 = -6.0 * (a1 * a6 + a3 * a5) +
          emsq * (-24.0 * (x2 * x7 + x1 * x8) - 6.0 * (x3 * x6 + x4 * x5));
  t.z13 = -6.0 * a3 * a6 + emsq * (-24.0 * x2 * x8 - 6.0 * x4 * x6);
  t.z21 = 6.0 * a2 * a5 + emsq * (24.0 * x1 * x5 - 6.0 * x3 * x7);
  t.z22 = 6.0 * (a4 * a5 + a2 * a6) +
          emsq * (24.0 * (x2 * x5 + x1 * x6) - 6.0 * (x4 * x7 + x3 * x8));
  t.z23 = 6.0 * a4 * a6 + emsq * (24.0 * x2 * x6 - 6.0 * x4 * x8);
  t.z1 = t.z1 + t.z1 + o.betasq * t.z31;
  t.z2 = t.z2 + t.z2 + o.betasq * t.z32;
  t.z3 = t.z3 + t.z3 + o.betasq * t.z33;
  t.s3 = b.cc * o.xnoi;
  t.s2 = -0.5 * t.s3 / o.rtemsq;
  t.s4 = t.s3 * o.rtemsq;
  t.s1 = -15.0 * o.em * t.s4;
  t.s5 = x1 * x3 + x2 * x4;
  t.s6 = x2 * x3 + x1 * x4;
  t.s7 = x2 * x4 - x1 * x3;
  return t;
}

struct Dscom {
  OrbitAngles o;
  BodyTerms sun, moon;
  LunarSolarPeriodics p;
};

// dscom: the Sun's and the Moon's geometry at epoch and the periodic coefficients.
Dscom dscom(const DeepSpaceEpoch& ep) {
  Dscom d{};
  OrbitAngles& o = d.o;
  o.sinim = std::sin(ep.inclo);
  o.cosim = std::cos(ep.inclo);
  o.sinomm = std::sin(ep.argpo);
  o.cosomm = std::cos(ep.argpo);
  o.em = ep.ecco;
  o.emsq = o.em * o.em;
  o.betasq = 1.0 - o.emsq;
  o.rtemsq = std::sqrt(o.betasq);
  o.xnoi = 1.0 / ep.no_unkozai;
  const double snodm = std::sin(ep.nodeo), cnodm = std::cos(ep.nodeo);
  const double day = ep.epoch_days_1950 + 18261.5;  // days since 2000 Jan 0.5 (tc = 0)
  const double xnodce = detail::fmod_two_pi(4.5236020 - 9.2422029e-4 * day);
  const double stem = std::sin(xnodce), ctem = std::cos(xnodce);
  const double zcosil = 0.91375164 - 0.03568096 * ctem;
  const double zsinil = std::sqrt(1.0 - zcosil * zcosil);
  const double zsinhl = 0.089683511 * stem / zsinil;
  const double zcoshl = std::sqrt(1.0 - zsinhl * zsinhl);
  const double gam = 5.8351514 + 0.0019443680 * day;
  double zx = 0.39785416 * stem / zsinil;
  const double zy = zcoshl * ctem + 0.91744867 * zsinhl * stem;
  zx = gam + std::atan2(zx, zy) - xnodce;
  const BodyAxes sun{0.1945905, -0.98088458, 0.91744867, 0.39785416, cnodm, snodm, 2.9864797e-6};
  const BodyAxes moon{std::cos(zx), std::sin(zx), zcosil, zsinil,
                      zcoshl * cnodm + zsinhl * snodm, snodm * zcoshl - cnodm * zsinhl,
                      4.7968065e-7};
  d.sun = body_terms(sun, o);
  d.moon = body_terms(moon, o);
  const BodyTerms& s = d.sun;
  const BodyTerms& m = d.moon;
  LunarSolarPeriodics& p = d.p;
  p.zmol = detail::fmod_two_pi(4.7199672 + 0.22997150 * day - gam);
  p.zmos = detail::fmod_two_pi(6.2565837 + 0.017201977 * day);
  p.se2 = 2.0 * s.s1 * s.s6;
  p.se3 = 2.0 * s.s1 * s.s7;
  p.si2 = 2.0 * s.s2 * s.z12;
  p.si3 = 2.0 * s.s2 * (s.z13 - s.z11);
  p.sl2 = -2.0 * s.s3 * s.z2;
  p.sl3 = -2.0 * s.s3 * (s.z3 - s.z1);
  p.sl4 = -2.0 * s.s3 * (-21.0 - 9.0 * o.emsq) * kZes;
  p.sgh2 = 2.0 * s.s4 * s.z32;
  p.sgh3 = 2.0 * s.s4 * (s.z33 - s.z31);
  p.sgh4 = -18.0 * s.s4 * kZes;
  p.sh2 = -2.0 * s.s2 * s.z22;
  p.sh3 = -2.0 * s.s2 * (s.z23 - s.z21);
  p.ee2 = 2.0 * m.s1 * m.s6;
  p.e3 = 2.0 * m.s1 * m.s7;
  p.xi2 = 2.0 * m.s2 * m.z12;
  p.xi3 = 2.0 * m.s2 * (m.z13 - m.z11);
  p.xl2 = -2.0 * m.s3 * m.z2;
  p.xl3 = -2.0 * m.s3 * (m.z3 - m.z1);
  p.xl4 = -2.0 * m.s3 * (-21.0 - 9.0 * o.emsq) * kZel;
  p.xgh2 = 2.0 * m.s4 * m.z32;
  p.xgh3 = 2.0 * m.s4 * (m.z33 - m.z31);
  p.xgh4 = -18.0 * m.s4 * kZel;
  p.xh2 = -2.0 * m.s2 * m.z22;
  p.xh3 = -2.0 * m.s2 * (m.z23 - m.z21);
  return d;
}

// dsinit, first part: the lunar-solar secular rates.
void secular_rates(const Dscom& d, double inclm, DeepSpaceTerms& ds) {
  const OrbitAngles& o = d.o;
  const BodyTerms& s = d.sun;
  const BodyTerms& m = d.moon;
  const bool near_equatorial = inclm < 5.2359877e-2 || inclm > kPi - 5.2359877e-2;
  const double ses = s.s1 * kZns * s.s5;
  const double sis = s.s2 * kZns * (s.z11 + s.z13);
  const double sls = -kZns * s.s3 * (s.z1 + s.z3 - 14.0 - 6.0 * o.emsq);
  const double sghs = s.s4 * kZns * (s.z31 + s.z33 - 6.0);
  double shs = near_equatorial ? 0.0 : -kZns * s.s2 * (s.z21 + s.z23);
  if (o.sinim != 0.0) shs = shs / o.sinim;
  const double sgs = sghs - o.cosim * shs;
  ds.dedt = ses + m.s1 * kZnl * m.s5;
  ds.didt = sis + m.s2 * kZnl * (m.z11 + m.z13);
  ds.dmdt = sls - kZnl * m.s3 * (m.z1 + m.z3 - 14.0 - 6.0 * o.emsq);
  const double sghl = m.s4 * kZnl * (m.z31 + m.z33 - 6.0);
  const double shll = near_equatorial ? 0.0 : -kZnl * m.s2 * (m.z21 + m.z23);
  ds.domdt = sgs + sghl;
  ds.dnodt = shs;
  if (o.sinim != 0.0) {
    ds.domdt = ds.domdt - o.cosim / o.sinim * shll;
    ds.dnodt = ds.dnodt + shll / o.sinim;
  }
}

// The eccentricity functions G_lmpq of the 12 h resonance (polynomial fits in e).
struct HalfDayG {
  double g201, g211, g310, g322, g410, g422, g520, g521, g532, g533;
};

HalfDayG half_day_g(double em) {
  const double emsq = em * em, eoc = em * emsq;
  HalfDayG g{};
  g.g201 = -0.306 - (em - 0.64) * 0.440;
  if (em <= 0.65) {
    g.g211 = 3.616 - 13.2470 * em + 16.2900 * emsq;
    g.g310 = -19.302 + 117.3900 * em - 228.4190 * emsq + 156.5910 * eoc;
    g.g322 = -18.9068 + 109.7927 * em - 214.6334 * emsq + 146.5816 * eoc;
    g.g410 = -41.122 + 242.6940 * em - 471.0940 * emsq + 313.9530 * eoc;
    g.g422 = -146.407 + 841.8800 * em - 1629.014 * emsq + 1083.4350 * eoc;
    g.g520 = -532.114 + 3017.977 * em - 5740.032 * emsq + 3708.2760 * eoc;
  } else {
    g.g211 = -72.099 + 331.819 * em - 508.738 * emsq + 266.724 * eoc;
    g.g310 = -346.844 + 1582.851 * em - 2415.925 * emsq + 1246.113 * eoc;
    g.g322 = -342.585 + 1554.908 * em - 2366.899 * emsq + 1215.972 * eoc;
    g.g410 = -1052.797 + 4758.686 * em - 7193.992 * emsq + 3651.957 * eoc;
    g.g422 = -3581.690 + 16178.110 * em - 24462.770 * emsq + 12422.520 * eoc;
    g.g520 = em > 0.715 ? -5149.66 + 29936.92 * em - 54087.36 * emsq + 31324.56 * eoc
                        : 1464.74 - 4664.75 * em + 3763.64 * emsq;
  }
  if (em < 0.7) {
    g.g533 = -919.22770 + 4988.6100 * em - 9064.7700 * emsq + 5542.21 * eoc;
    g.g521 = -822.71072 + 4568.6173 * em - 8491.4146 * emsq + 5337.524 * eoc;
    g.g532 = -853.66600 + 4690.2500 * em - 8624.7700 * emsq + 5341.4 * eoc;
  } else {
    g.g533 = -37995.780 + 161616.52 * em - 229838.20 * emsq + 109377.94 * eoc;
    g.g521 = -51752.104 + 218913.95 * em - 309468.16 * emsq + 146349.42 * eoc;
    g.g532 = -40023.880 + 170470.89 * em - 242699.48 * emsq + 115605.82 * eoc;
  }
  return g;
}

// dsinit, 12 h resonance (Molniya-type: n near 2 rev/day, e >= 0.5).
void half_day_resonance(const DeepSpaceEpoch& ep, const OrbitAngles& o, double aonv,
                        double theta, DeepSpaceTerms& ds) {
  Resonance& r = ds.resonance;
  const HalfDayG g = half_day_g(ep.ecco);
  const double sinim = o.sinim, cosim = o.cosim, cosisq = cosim * cosim;
  const double sini2 = sinim * sinim;
  const double f220 = 0.75 * (1.0 + 2.0 * cosim + cosisq);
  const double f221 = 1.5 * sini2;
  const double f321 = 1.875 * sinim * (1.0 - 2.0 * cosim - 3.0 * cosisq);
  const double f322 = -1.875 * sinim * (1.0 + 2.0 * cosim - 3.0 * cosisq);
  const double f441 = 35.0 * sini2 * f220;
  const double f442 = 39.3750 * sini2 * sini2;
  const double f522 = 9.84375 * sinim *
                      (sini2 * (1.0 - 2.0 * cosim - 5.0 * cosisq) +
                       0.33333333 * (-2.0 + 4.0 * cosim + 6.0 * cosisq));
  const double f523 = sinim * (4.92187512 * sini2 * (-2.0 - 4.0 * cosim + 10.0 * cosisq) +
                               6.56250012 * (1.0 + 2.0 * cosim - 3.0 * cosisq));
  const double f542 = 29.53125 * sinim *
                      (2.0 - 8.0 * cosim + cosisq * (-12.0 + 8.0 * cosim + 10.0 * cosisq));
  const double f543 = 29.53125 * sinim *
                      (-2.0 - 8.0 * cosim + cosisq * (12.0 + 8.0 * cosim - 10.0 * cosisq));
  const double nm = ep.no_unkozai;
  double temp1 = 3.0 * nm * nm * aonv * aonv;
  double temp = temp1 * 1.7891679e-6;  // root22
  r.d2201 = temp * f220 * g.g201;
  r.d2211 = temp * f221 * g.g211;
  temp1 = temp1 * aonv;
  temp = temp1 * 3.7393792e-7;  // root32
  r.d3210 = temp * f321 * g.g310;
  r.d3222 = temp * f322 * g.g322;
  temp1 = temp1 * aonv;
  temp = 2.0 * temp1 * 7.3636953e-9;  // root44
  r.d4410 = temp * f441 * g.g410;
  r.d4422 = temp * f442 * g.g422;
  temp1 = temp1 * aonv;
  temp = temp1 * 1.1428639e-7;  // root52
  r.d5220 = temp * f522 * g.g520;
  r.d5232 = temp * f523 * g.g532;
  temp = 2.0 * temp1 * 2.1765803e-9;  // root54
  r.d5421 = temp * f542 * g.g521;
  r.d5433 = temp * f543 * g.g533;
  r.xlamo = detail::fmod_two_pi(ep.mo + ep.nodeo + ep.nodeo - theta - theta);
  r.xfact = ep.mdot + ds.dmdt + 2.0 * (ep.nodedot + ds.dnodt - kRptim) - ep.no_unkozai;
}

// dsinit, 24 h resonance (geosynchronous: period between 1200 and 1800 min).
void synchronous_resonance(const DeepSpaceEpoch& ep, const OrbitAngles& o, double aonv,
                           double theta, DeepSpaceTerms& ds) {
  Resonance& r = ds.resonance;
  const double emsq = o.emsq, cosim = o.cosim, sinim = o.sinim;
  const double g200 = 1.0 + emsq * (-2.5 + 0.8125 * emsq);
  const double g310 = 1.0 + 2.0 * emsq;
  const double g300 = 1.0 + emsq * (-6.0 + 6.60937 * emsq);
  const double f220 = 0.75 * (1.0 + cosim) * (1.0 + cosim);
  const double f311 = 0.9375 * sinim * sinim * (1.0 + 3.0 * cosim) - 0.75 * (1.0 + cosim);
  double f330 = 1.0 + cosim;
  f330 = 1.875 * f330 * f330 * f330;
  const double nm = ep.no_unkozai;
  const double del1 = 3.0 * nm * nm * aonv * aonv;
  r.del2 = 2.0 * del1 * f220 * g200 * 1.7891679e-6;         // q22
  r.del3 = 3.0 * del1 * f330 * g300 * 2.2123015e-7 * aonv;  // q33
  r.del1 = del1 * f311 * g310 * 2.1460748e-6 * aonv;        // q31
  r.xlamo = detail::fmod_two_pi(ep.mo + ep.nodeo + ep.argpo - theta);
  r.xfact = ep.mdot + (ep.argpdot + ep.nodedot) - kRptim + ds.dmdt + ds.domdt + ds.dnodt -
            ep.no_unkozai;
}

// Resonance rates at the integrator's state (dspace's loop body).
struct ResonanceRates {
  double xndt, xldot, xnddt;
};

ResonanceRates resonance_rates(const Resonance& r, const DeepSpaceEpoch& ep, double xli,
                               double xni, double atime) {
  constexpr double fasx2 = 0.13130908, fasx4 = 2.8843198, fasx6 = 0.37448087;
  constexpr double g22 = 5.7686396, g32 = 0.95240898, g44 = 1.8014998, g52 = 1.0508330,
                   g54 = 4.4108898;
  ResonanceRates k{};
  k.xldot = xni + r.xfact;
  if (r.irez != 2) {
    k.xndt = r.del1 * std::sin(xli - fasx2) + r.del2 * std::sin(2.0 * (xli - fasx4)) +
             r.del3 * std::sin(3.0 * (xli - fasx6));
    k.xnddt = r.del1 * std::cos(xli - fasx2) + 2.0 * r.del2 * std::cos(2.0 * (xli - fasx4)) +
              3.0 * r.del3 * std::cos(3.0 * (xli - fasx6));
  } else {
    const double xomi = ep.argpo + ep.argpdot * atime;
    const double x2omi = xomi + xomi, x2li = xli + xli;
    k.xndt = r.d2201 * std::sin(x2omi + xli - g22) + r.d2211 * std::sin(xli - g22) +
             r.d3210 * std::sin(xomi + xli - g32) + r.d3222 * std::sin(-xomi + xli - g32) +
             r.d4410 * std::sin(x2omi + x2li - g44) + r.d4422 * std::sin(x2li - g44) +
             r.d5220 * std::sin(xomi + xli - g52) + r.d5232 * std::sin(-xomi + xli - g52) +
             r.d5421 * std::sin(xomi + x2li - g54) + r.d5433 * std::sin(-xomi + x2li - g54);
    k.xnddt = r.d2201 * std::cos(x2omi + xli - g22) + r.d2211 * std::cos(xli - g22) +
              r.d3210 * std::cos(xomi + xli - g32) + r.d3222 * std::cos(-xomi + xli - g32) +
              r.d5220 * std::cos(xomi + xli - g52) + r.d5232 * std::cos(-xomi + xli - g52) +
              2.0 * (r.d4410 * std::cos(x2omi + x2li - g44) + r.d4422 * std::cos(x2li - g44) +
                     r.d5421 * std::cos(xomi + x2li - g54) +
                     r.d5433 * std::cos(-xomi + x2li - g54));
  }
  k.xnddt = k.xnddt * k.xldot;
  return k;
}

// One step of dspace's loop from state s with the rates k there (delt = +-720 min).
ResonanceCheckpoint resonance_step(const ResonanceCheckpoint& s, const ResonanceRates& k,
                                   double delt) {
  ResonanceCheckpoint n;
  n.xli = s.xli + k.xldot * delt + k.xndt * kStep2;
  n.xni = s.xni + k.xndt * delt + k.xnddt * kStep2;
  n.atime = s.atime + delt;
  return n;
}

// The states of dspace's loop after 0, 1, ... steps toward t > 0, up to the horizon.
std::vector<ResonanceCheckpoint> resonance_checkpoints(const Resonance& r,
                                                       const DeepSpaceEpoch& ep) {
  const auto n = static_cast<std::size_t>(kResonanceCheckpointHorizonMin / kStep);
  std::vector<ResonanceCheckpoint> c;
  c.reserve(n + 1);
  c.push_back(ResonanceCheckpoint{0.0, r.xlamo, ep.no_unkozai});
  for (std::size_t k = 0; k <= n; ++k) {
    ResonanceCheckpoint& s = c.back();
    const ResonanceRates rates = resonance_rates(r, ep, s.xli, s.xni, s.atime);
    s.xndt = rates.xndt;
    s.xldot = rates.xldot;
    s.xnddt = rates.xnddt;
    if (k < n) c.push_back(resonance_step(s, rates, kStep));
  }
  return c;
}

}  // namespace

DeepSpaceTerms deep_space_init(const DeepSpaceEpoch& ep) {
  DeepSpaceTerms ds;
  const Dscom d = dscom(ep);
  ds.periodics = d.p;
  secular_rates(d, ep.inclo, ds);
  const double nm = ep.no_unkozai;
  int irez = 0;
  if (nm > 0.0034906585 && nm < 0.0052359877) irez = 1;
  if (nm >= 8.26e-3 && nm <= 9.24e-3 && ep.ecco >= 0.5) irez = 2;
  ds.resonance.irez = irez;
  if (irez == 0) return ds;
  const double theta = detail::fmod_two_pi(ep.gsto);
  const double aonv = std::pow(nm / ep.xke, 2.0 / 3.0);
  if (irez == 2) half_day_resonance(ep, d.o, aonv, theta, ds);
  if (irez == 1) synchronous_resonance(ep, d.o, aonv, theta, ds);
  ds.checkpoints = resonance_checkpoints(ds.resonance, ep);
  return ds;
}

void deep_space_secular(const DeepSpaceTerms& ds, const DeepSpaceEpoch& ep, double t,
                        DeepSpaceMean& m) {
  const double theta = detail::fmod_two_pi(ep.gsto + t * kRptim);
  m.em += ds.dedt * t;
  m.inclm += ds.didt * t;
  m.argpm += ds.domdt * t;
  m.nodem += ds.dnodt * t;
  m.mm += ds.dmdt * t;
  const Resonance& r = ds.resonance;
  if (r.irez == 0) return;
  if (!std::isfinite(t)) {  // the loop below would never reach t: no mean motion (NaN)
    m.nm = std::numeric_limits<double>::quiet_NaN();
    return;
  }
  ResonanceCheckpoint s{0.0, r.xlamo, ep.no_unkozai};
  double ft = 0.0;
  const double delt = t > 0.0 ? kStep : -kStep;
  // The loop below passes step j without stopping while t - 720 j >= 720: start from the
  // checkpoint floor(t / 720) - 1 (at least the first, at most the last one), which is the
  // loop's own state there; from a checkpoint, the loop's next state is the next checkpoint
  // and the rates are the ones stored with it (resonance_checkpoints computed both the same way).
  const std::size_t kNone = ds.checkpoints.size();
  std::size_t at = kNone;  // s is checkpoint `at`, or no checkpoint
  if (t > 0.0 && !ds.checkpoints.empty()) {
    const double last = static_cast<double>(ds.checkpoints.size() - 1);
    at = static_cast<std::size_t>(std::clamp(std::floor(t / kStep) - 1.0, 0.0, last));
    s = ds.checkpoints[at];
  }
  ResonanceRates k{};
  for (;;) {  // at most 2 steps after a checkpoint within the horizon
    k = at != kNone ? ResonanceRates{s.xndt, s.xldot, s.xnddt}
                    : resonance_rates(r, ep, s.xli, s.xni, s.atime);
    if (std::fabs(t - s.atime) < kStep) {
      ft = t - s.atime;
      break;
    }
    if (at != kNone && at + 1 < ds.checkpoints.size()) {
      s = ds.checkpoints[++at];
    } else {
      at = kNone;
      s = resonance_step(s, k, delt);
    }
  }
  const double nm = s.xni + k.xndt * ft + k.xnddt * ft * ft * 0.5;
  const double xl = s.xli + k.xldot * ft + k.xndt * ft * ft * 0.5;
  if (r.irez != 1) {
    m.mm = xl - 2.0 * m.nodem + 2.0 * theta;
  } else {
    m.mm = xl - m.nodem - m.argpm + theta;
  }
  m.nm = ep.no_unkozai + (nm - ep.no_unkozai);
}

void deep_space_periodics(const LunarSolarPeriodics& p, double t, OperationMode mode,
                          PerturbedElements& e) {
  // Solar terms.
  double zm = p.zmos + kZns * t;
  double zf = zm + 2.0 * kZes * std::sin(zm);
  double sinzf = std::sin(zf);
  double f2 = 0.5 * sinzf * sinzf - 0.25;
  double f3 = -0.5 * sinzf * std::cos(zf);
  const double ses = p.se2 * f2 + p.se3 * f3;
  const double sis = p.si2 * f2 + p.si3 * f3;
  const double sls = p.sl2 * f2 + p.sl3 * f3 + p.sl4 * sinzf;
  const double sghs = p.sgh2 * f2 + p.sgh3 * f3 + p.sgh4 * sinzf;
  const double shs = p.sh2 * f2 + p.sh3 * f3;
  // Lunar terms.
  zm = p.zmol + kZnl * t;
  zf = zm + 2.0 * kZel * std::sin(zm);
  sinzf = std::sin(zf);
  f2 = 0.5 * sinzf * sinzf - 0.25;
  f3 = -0.5 * sinzf * std::cos(zf);
  const double sel = p.ee2 * f2 + p.e3 * f3;
  const double sil = p.xi2 * f2 + p.xi3 * f3;
  const double sll = p.xl2 * f2 + p.xl3 * f3 + p.xl4 * sinzf;
  const double sghl = p.xgh2 * f2 + p.xgh3 * f3 + p.xgh4 * sinzf;
  const double shll = p.xh2 * f2 + p.xh3 * f3;
  // The reference subtracts the values at epoch (peo, pinco, ...), which it sets to zero.
  const double pe = ses + sel, pinc = sis + sil, pl = sls + sll;
  double pgh = sghs + sghl, ph = shs + shll;
  e.inclp += pinc;
  e.ep += pe;
  const double sinip = std::sin(e.inclp), cosip = std::cos(e.inclp);
  if (e.inclp >= 0.2) {
    ph /= sinip;
    pgh -= cosip * ph;
    e.argpp += pgh;
    e.nodep += ph;
    e.mp += pl;
    return;
  }
  // Lyddane modification for low inclination.
  const double sinop = std::sin(e.nodep), cosop = std::cos(e.nodep);
  double alfdp = sinip * sinop, betdp = sinip * cosop;
  alfdp += ph * cosop + pinc * cosip * sinop;
  betdp += -ph * sinop + pinc * cosip * cosop;
  e.nodep = detail::fmod_two_pi(e.nodep);
  if (e.nodep < 0.0 && mode == OperationMode::kAfspc) e.nodep += kTwoPi;
  const double xls = e.mp + e.argpp + pl + pgh + (cosip - pinc * sinip) * e.nodep;
  const double xnoh = e.nodep;
  e.nodep = std::atan2(alfdp, betdp);
  if (e.nodep < 0.0 && mode == OperationMode::kAfspc) e.nodep += kTwoPi;
  if (std::fabs(xnoh - e.nodep) > kPi) e.nodep += e.nodep < xnoh ? kTwoPi : -kTwoPi;
  e.mp += pl;
  e.argpp = xls - e.mp - cosip * e.nodep;
}

}  // namespace evade::sgp4
