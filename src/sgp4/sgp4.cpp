// SGP4/SDP4: Vallado, Crawford, Hujsak & Kelso (2006), "Revisiting Spacetrack Report #3",
// AIAA 2006-6753, after Hoots & Roehrich (1980), Spacetrack Report #3. sgp4init: recover
// the Brouwer mean motion from the Kozai one (STR#3 eq. for a1, delta1, a0, delta0), the
// atmospheric density function (s, q0 - s)^4 with the perigee-dependent s, the drag
// coefficients C1..C5 and D2..D4, and the secular rates of M, omega and Omega from J2 and J4.
// sgp4: secular gravity and drag, long-period periodics (J3: aycof, xlcof), Kepler's
// equation in the Lyddane variables (Newton, at most 10 iterations, step limited to 0.95),
// short-period J2 terms, and the unit vectors U, V giving r and v in TEME. The deep-space
// branch (period >= 225 min) is in deep_space.cpp. Where the reference computes the sine and
// cosine of an angle a small step d from one whose sine and cosine it has (Newton's iterates;
// the argument of latitude and the inclination plus their short-period corrections), they
// are rotated by d here (rotate), and am^1.5 is am sqrt(am): the same numbers within a few
// roundings (the SGP4-VER figures in docs/ASSESSMENT.md), a quarter of the time.
#include "evade/sgp4/sgp4.hpp"
#include "angles.hpp"

#include <cmath>
#include <limits>

namespace evade::sgp4 {
namespace {

using detail::kPi;
using detail::kTwoPi;
constexpr double kDeg2Rad = kPi / 180.0;
constexpr double kX2o3 = 2.0 / 3.0;
constexpr double kTemp4 = 1.5e-12;  // guard of the 1 / (1 + cos i) in xlcof at i = 180 deg

Sgp4State failed(Sgp4Error e) noexcept {
  Sgp4State s;
  s.error = e;
  s.r_teme_m.setConstant(std::numeric_limits<double>::quiet_NaN());
  s.v_teme_mps.setConstant(std::numeric_limits<double>::quiet_NaN());
  return s;
}

// Greenwich sidereal angle at epoch in the AFSPC way (days since 1970, FK5 rate).
double gsto_afspc(double epoch_days_1950) noexcept {
  const double ts70 = epoch_days_1950 - 7305.0;
  const double ds70 = std::floor(ts70 + 1.0e-8);
  const double tfrac = ts70 - ds70;
  const double c1 = 1.72027916940703639e-2;
  const double thgr70 = 1.7321343856509374;
  const double fk5r = 5.07551419432269442e-15;
  const double c1p2p = c1 + kTwoPi;
  double gsto = detail::fmod_two_pi(thgr70 + c1 * ds70 + c1p2p * tfrac + ts70 * ts70 * fk5r);
  if (gsto < 0.0) gsto += kTwoPi;
  return gsto;
}

double xlcof_of(double j3oj2, double sini, double cosi) noexcept {
  const double den = std::fabs(cosi + 1.0) > 1.5e-12 ? 1.0 + cosi : kTemp4;
  return -0.25 * j3oj2 * sini * (3.0 + 5.0 * cosi) / den;
}

// The sine and cosine of an angle.
struct SinCos {
  double s, c;
};

// Angle steps below which a sine and cosine are rotated rather than recomputed [rad].
constexpr double kSmallAngle = 1e-2;

// sin and cos of a + d from those of a, for |d| <= kSmallAngle: the angle-sum formulas with
// sin d and cos d from their Taylor series through d^7 and d^8 (remainders below
// |d|^9 / 9! = 3e-24 and |d|^10 / 10! = 3e-27 at |d| = 1e-2, far below the 1.1e-16 of one
// rounding), so the result is within a few roundings of std::sin and std::cos of a + d.
inline SinCos rotate(SinCos a, double d) noexcept {
  const double d2 = d * d;
  const double sd = d * (1.0 + d2 * (-1.0 / 6.0 + d2 * (1.0 / 120.0 + d2 * (-1.0 / 5040.0))));
  const double cd = 1.0 + d2 * (-0.5 + d2 * (1.0 / 24.0 + d2 * (-1.0 / 720.0 + d2 * (1.0 / 40320.0))));
  return {a.s * cd + a.c * sd, a.c * cd - a.s * sd};
}

// sin and cos of the angle b = a + d, given those of a (sc_a): rotated for a small d, else
// std::sin and std::cos of b.
SinCos sincos_plus(SinCos sc_a, double b, double d) noexcept {
  if (std::fabs(d) <= kSmallAngle) return rotate(sc_a, d);
  return {std::sin(b), std::cos(b)};
}

// sin and cos of atan2(s, c) + d: (s, c) normalised and rotated for a small d, else the
// reference's atan2, sin and cos.
SinCos angle_plus(double s, double c, double d) noexcept {
  if (std::fabs(d) <= kSmallAngle) {
    const double norm = std::sqrt(s * s + c * c);
    return rotate({s / norm, c / norm}, d);
  }
  const double a = std::atan2(s, c) + d;
  return {std::sin(a), std::cos(a)};
}

// Kepler's equation in the Lyddane variables: returns the sine and cosine of E + omega from
// the last Newton iteration, as the reference keeps them. Each iterate's sine and cosine
// come from the previous iterate's rotated by the Newton step when that is small (sincos_plus):
// in LEO one sin and cos per call instead of one per iteration, the same values within a
// few roundings.
SinCos solve_kepler(double u, double axnl, double aynl) noexcept {
  double eo1 = u, tem5 = 9999.9, step = 0.0;
  SinCos sc{std::sin(u), std::cos(u)};
  for (int ktr = 1; std::fabs(tem5) >= 1.0e-12 && ktr <= 10; ++ktr) {
    if (ktr > 1) sc = sincos_plus(sc, eo1, step);
    tem5 = 1.0 - sc.c * axnl - sc.s * aynl;
    tem5 = (u - aynl * sc.c + axnl * sc.s - eo1) / tem5;
    if (std::fabs(tem5) >= 0.95) tem5 = tem5 > 0.0 ? 0.95 : -0.95;
    step = tem5;
    eo1 = eo1 + tem5;
  }
  return sc;
}

}  // namespace

const char* sgp4_error_text(Sgp4Error e) noexcept {
  switch (e) {
    case Sgp4Error::kNone: return "no error";
    case Sgp4Error::kMeanEccentricity: return "mean eccentricity out of [-0.001, 1) (error 1)";
    case Sgp4Error::kMeanMotion: return "mean motion not positive (error 2)";
    case Sgp4Error::kPerturbedEccentricity:
      return "perturbed eccentricity out of [0, 1] (error 3)";
    case Sgp4Error::kSemiLatusRectum: return "semi-latus rectum negative (error 4)";
    case Sgp4Error::kSubOrbital: return "epoch elements sub-orbital (error 5)";
    case Sgp4Error::kDecayed: return "satellite decayed: radius below 1 Earth radius (error 6)";
  }
  return "unknown error";
}

double gmst_iau82_rad(double jd_ut1) noexcept {
  const double tut1 = (jd_ut1 - 2451545.0) / 36525.0;
  double temp = -6.2e-6 * tut1 * tut1 * tut1 + 0.093104 * tut1 * tut1 +
                (876600.0 * 3600 + 8640184.812866) * tut1 + 67310.54841;  // s
  temp = detail::fmod_two_pi(temp * kDeg2Rad / 240.0);  // 360 deg / 86400 s = 1 / 240
  if (temp < 0.0) temp += kTwoPi;
  return temp;
}

Sgp4Elements sgp4_elements(const MeanElements& m) noexcept {
  const double xpdotp = 1440.0 / (2.0 * kPi);  // rev/day -> rad/min
  Sgp4Elements e;
  const SplitJulianDate jd = epoch_julian_date(m);
  e.epoch_days_1950 = (jd.day - 2433281.5) + jd.fraction;
  e.bstar_per_er = m.bstar_per_er;
  e.ecco = m.eccentricity;
  e.inclo_rad = m.inclination_deg * kDeg2Rad;
  e.nodeo_rad = m.raan_deg * kDeg2Rad;
  e.argpo_rad = m.arg_perigee_deg * kDeg2Rad;
  e.mo_rad = m.mean_anomaly_deg * kDeg2Rad;
  e.no_kozai_radpmin = m.mean_motion_revpday / xpdotp;
  return e;
}

Sgp4Propagator::Sgp4Propagator(const MeanElements& m, OperationMode mode, GravityModel gravity)
    : Sgp4Propagator(sgp4_elements(m), mode, gravity) {}

Sgp4Propagator::Sgp4Propagator(const Sgp4Elements& el, OperationMode mode,
                               GravityModel gravity)
    : k_(gravity_constants(gravity)), mode_(mode), el_(el) {
  // initl: un-Kozai the mean motion.
  const double ecco = el.ecco, inclo = el.inclo_rad;
  const double eccsq = ecco * ecco;
  const double omeosq = 1.0 - eccsq;
  const double rteosq = std::sqrt(omeosq);
  const double cosio = std::cos(inclo);
  const double cosio2 = cosio * cosio;
  const double ak = std::pow(k_.xke_per_min / el.no_kozai_radpmin, kX2o3);
  const double d1 = 0.75 * k_.j2 * (3.0 * cosio2 - 1.0) / (rteosq * omeosq);
  double del = d1 / (ak * ak);
  const double adel = ak * (1.0 - del * del - del * (1.0 / 3.0 + 134.0 * del * del / 81.0));
  del = d1 / (adel * adel);
  no_unkozai_ = el.no_kozai_radpmin / (1.0 + del);
  const double ao = std::pow(k_.xke_per_min / no_unkozai_, kX2o3);
  const double sinio = std::sin(inclo);
  const double po = ao * omeosq;
  const double posq = po * po;
  const double rp = ao * (1.0 - ecco);
  ep_.gsto = mode == OperationMode::kAfspc ? gsto_afspc(el.epoch_days_1950)
                                           : gmst_iau82_rad(el.epoch_days_1950 + 2433281.5);
  ep_.epoch_days_1950 = el.epoch_days_1950;
  ep_.ecco = ecco;
  ep_.inclo = inclo;
  ep_.nodeo = el.nodeo_rad;
  ep_.argpo = el.argpo_rad;
  ep_.mo = el.mo_rad;
  ep_.no_unkozai = no_unkozai_;
  ep_.xke = k_.xke_per_min;
  if (omeosq >= 0.0 || no_unkozai_ >= 0.0) {
    init_near_earth(ao, posq, rteosq, omeosq, cosio, sinio, rp);
    if (2.0 * kPi / no_unkozai_ >= 225.0) {
      deep_ = true;
      isimp_ = true;
      ds_ = deep_space_init(ep_);
    }
  }
  sin_inclo_ = std::sin(el_.inclo_rad);
  cos_inclo_ = std::cos(el_.inclo_rad);
  am_near_ = std::pow(k_.xke_per_min / no_unkozai_, kX2o3);
  init_error_ = propagate_min(0.0).error;
}

void Sgp4Propagator::init_near_earth(double ao, double posq, double rteosq, double omeosq,
                                     double cosio, double sinio, double rp) {
  const double re = k_.radius_km, j2 = k_.j2, ecco = el_.ecco, bstar = el_.bstar_per_er;
  const double no = no_unkozai_, cosio2 = cosio * cosio;
  const double con42 = 1.0 - 5.0 * cosio2;
  near_.con41 = -con42 - cosio2 - cosio2;
  isimp_ = rp < 220.0 / re + 1.0;
  // Density function: s = 78 km above the surface unless perigee is below 156 km.
  double sfour = 78.0 / re + 1.0;
  const double qzms2ttemp = (120.0 - 78.0) / re;
  double qzms24 = qzms2ttemp * qzms2ttemp * qzms2ttemp * qzms2ttemp;
  const double perige = (rp - 1.0) * re;
  if (perige < 156.0) {
    sfour = perige < 98.0 ? 20.0 : perige - 78.0;
    const double qzms24temp = (120.0 - sfour) / re;
    qzms24 = qzms24temp * qzms24temp * qzms24temp * qzms24temp;
    sfour = sfour / re + 1.0;
  }
  const double pinvsq = 1.0 / posq;
  const double tsi = 1.0 / (ao - sfour);
  eta_ = ao * ecco * tsi;
  const double etasq = eta_ * eta_;
  const double eeta = ecco * eta_;
  const double psisq = std::fabs(1.0 - etasq);
  const double coef = qzms24 * std::pow(tsi, 4.0);
  const double coef1 = coef / std::pow(psisq, 3.5);
  const double cc2 = coef1 * no *
                     (ao * (1.0 + 1.5 * etasq + eeta * (4.0 + etasq)) +
                      0.375 * j2 * tsi / psisq * near_.con41 * (8.0 + 3.0 * etasq * (8.0 + etasq)));
  cc1_ = bstar * cc2;
  double cc3 = 0.0;
  if (ecco > 1.0e-4) cc3 = -2.0 * coef * tsi * k_.j3oj2 * no * sinio / ecco;
  near_.x1mth2 = 1.0 - cosio2;
  cc4_ = 2.0 * no * coef1 * ao * omeosq *
         (eta_ * (2.0 + 0.5 * etasq) + ecco * (0.5 + 2.0 * etasq) -
          j2 * tsi / (ao * psisq) *
              (-3.0 * near_.con41 * (1.0 - 2.0 * eeta + etasq * (1.5 - 0.5 * eeta)) +
               0.75 * near_.x1mth2 * (2.0 * etasq - eeta * (1.0 + etasq)) *
                   std::cos(2.0 * el_.argpo_rad)));
  cc5_ = 2.0 * coef1 * ao * omeosq * (1.0 + 2.75 * (etasq + eeta) + eeta * etasq);
  const double cosio4 = cosio2 * cosio2;
  const double temp1 = 1.5 * j2 * pinvsq * no;
  const double temp2 = 0.5 * temp1 * j2 * pinvsq;
  const double temp3 = -0.46875 * k_.j4 * pinvsq * pinvsq * no;
  ep_.mdot = no + 0.5 * temp1 * rteosq * near_.con41 +
             0.0625 * temp2 * rteosq * (13.0 - 78.0 * cosio2 + 137.0 * cosio4);
  ep_.argpdot = (-0.5 * temp1 * con42 + 0.0625 * temp2 * (7.0 - 114.0 * cosio2 + 395.0 * cosio4) +
                 temp3 * (3.0 - 36.0 * cosio2 + 49.0 * cosio4));
  const double xhdot1 = -temp1 * cosio;
  ep_.nodedot = xhdot1 + (0.5 * temp2 * (4.0 - 19.0 * cosio2) + 2.0 * temp3 * (3.0 - 7.0 * cosio2)) * cosio;
  omgcof_ = bstar * cc3 * std::cos(el_.argpo_rad);
  xmcof_ = 0.0;
  if (ecco > 1.0e-4) xmcof_ = -kX2o3 * coef * bstar / eeta;
  nodecf_ = 3.5 * omeosq * xhdot1 * cc1_;
  t2cof_ = 1.5 * cc1_;
  near_.xlcof = xlcof_of(k_.j3oj2, sinio, cosio);
  near_.aycof = -0.5 * k_.j3oj2 * sinio;
  const double delmotemp = 1.0 + eta_ * std::cos(el_.mo_rad);
  delmo_ = delmotemp * delmotemp * delmotemp;
  sinmao_ = std::sin(el_.mo_rad);
  near_.x7thm1 = 7.0 * cosio2 - 1.0;
  if (!isimp_ && !(2.0 * kPi / no >= 225.0)) init_drag_higher_order(ao, tsi, sfour);
}

void Sgp4Propagator::init_drag_higher_order(double ao, double tsi, double sfour) {
  const double cc1sq = cc1_ * cc1_;
  d2_ = 4.0 * ao * tsi * cc1sq;
  const double temp = d2_ * tsi * cc1_ / 3.0;
  d3_ = (17.0 * ao + sfour) * temp;
  d4_ = 0.5 * temp * ao * tsi * (221.0 * ao + 31.0 * sfour) * cc1_;
  t3cof_ = d2_ + 2.0 * cc1sq;
  t4cof_ = 0.25 * (3.0 * d3_ + cc1_ * (12.0 * d2_ + 10.0 * cc1sq));
  t5cof_ = 0.2 * (3.0 * d4_ + 12.0 * cc1_ * d3_ + 6.0 * d2_ * d2_ + 15.0 * cc1sq * (2.0 * d2_ + cc1sq));
}

Sgp4Propagator::Short Sgp4Propagator::short_period(double sinip, double cosip) const noexcept {
  if (!deep_) return near_;
  // Deep space: the long- and short-period coefficients follow the perturbed inclination.
  Short s;
  s.aycof = -0.5 * k_.j3oj2 * sinip;
  s.xlcof = xlcof_of(k_.j3oj2, sinip, cosip);
  const double cosisq = cosip * cosip;
  s.con41 = 3.0 * cosisq - 1.0;
  s.x1mth2 = 1.0 - cosisq;
  s.x7thm1 = 7.0 * cosisq - 1.0;
  return s;
}

Sgp4Error Sgp4Propagator::mean_min(double t, PerturbedElements& p, double& am,
                                   double& nm) const noexcept {
  // Secular gravity and atmospheric drag.
  const double xmdf = el_.mo_rad + ep_.mdot * t;
  const double argpdf = el_.argpo_rad + ep_.argpdot * t;
  const double nodedf = el_.nodeo_rad + ep_.nodedot * t;
  const double t2 = t * t;
  DeepSpaceMean m;
  m.argpm = argpdf;
  m.mm = xmdf;
  m.nodem = nodedf + nodecf_ * t2;
  double tempa = 1.0 - cc1_ * t;
  double tempe = el_.bstar_per_er * cc4_ * t;
  double templ = t2cof_ * t2;
  if (!isimp_) {
    const double delomg = omgcof_ * t;
    const double delmtemp = 1.0 + eta_ * std::cos(xmdf);
    const double delm = xmcof_ * (delmtemp * delmtemp * delmtemp - delmo_);
    const double temp = delomg + delm;
    m.mm = xmdf + temp;
    m.argpm = argpdf - temp;
    const double t3 = t2 * t, t4 = t3 * t;
    tempa = tempa - d2_ * t2 - d3_ * t3 - d4_ * t4;
    tempe = tempe + el_.bstar_per_er * cc5_ * (std::sin(m.mm) - sinmao_);
    templ = templ + t3cof_ * t3 + t4 * (t4cof_ + t * t5cof_);
  }
  m.nm = no_unkozai_;
  m.em = el_.ecco;
  m.inclm = el_.inclo_rad;
  if (deep_) deep_space_secular(ds_, ep_, t, m);
  if (m.nm <= 0.0) return Sgp4Error::kMeanMotion;
  // Without a resonance the mean motion stays no_unkozai_, whose am_near_ is the same power.
  const bool resonant = deep_ && ds_.resonance.irez != 0;
  am = (resonant ? std::pow(k_.xke_per_min / m.nm, kX2o3) : am_near_) * tempa * tempa;
  nm = k_.xke_per_min / (am * std::sqrt(am));  // am^1.5
  double em = m.em - tempe;
  if (em >= 1.0 || em < -0.001) return Sgp4Error::kMeanEccentricity;
  if (em < 1.0e-6) em = 1.0e-6;
  const double mm0 = m.mm + no_unkozai_ * templ;
  const double xlm = detail::fmod_two_pi(mm0 + m.argpm + m.nodem);
  p.nodep = detail::fmod_two_pi(m.nodem);
  p.argpp = detail::fmod_two_pi(m.argpm);
  p.mp = detail::fmod_two_pi(xlm - p.argpp - p.nodep);
  p.ep = em;
  p.inclp = m.inclm;
  return Sgp4Error::kNone;
}

Sgp4Error Sgp4Propagator::perturbed_min(double t, PerturbedElements& p, double& am,
                                        double& nm) const noexcept {
  const Sgp4Error e = mean_min(t, p, am, nm);
  if (e != Sgp4Error::kNone || !deep_) return e;
  deep_space_periodics(ds_.periodics, t, mode_, p);
  if (p.inclp < 0.0) {
    p.inclp = -p.inclp;
    p.nodep = p.nodep + kPi;
    p.argpp = p.argpp - kPi;
  }
  if (p.ep < 0.0 || p.ep > 1.0) return Sgp4Error::kPerturbedEccentricity;
  return Sgp4Error::kNone;
}

Sgp4State Sgp4Propagator::propagate_min(double t) const noexcept {
  PerturbedElements p;
  double am = 0.0, nm = 0.0;
  const Sgp4Error e = perturbed_min(t, p, am, nm);
  if (e != Sgp4Error::kNone) return failed(e);
  return position_velocity(p, am, nm);
}

Sgp4State Sgp4Propagator::position_velocity(const PerturbedElements& p, double am,
                                            double nm) const noexcept {
  const double sinip = deep_ ? std::sin(p.inclp) : sin_inclo_;
  const double cosip = deep_ ? std::cos(p.inclp) : cos_inclo_;
  const Short c = short_period(sinip, cosip);
  // Long-period periodics and Kepler's equation.
  const double axnl = p.ep * std::cos(p.argpp);
  double temp = 1.0 / (am * (1.0 - p.ep * p.ep));
  const double aynl = p.ep * std::sin(p.argpp) + temp * c.aycof;
  const double xl = p.mp + p.argpp + p.nodep + temp * c.xlcof * axnl;
  const double u = detail::fmod_two_pi(xl - p.nodep);
  const SinCos ks = solve_kepler(u, axnl, aynl);
  const double ecose = axnl * ks.c + aynl * ks.s;
  const double esine = axnl * ks.s - aynl * ks.c;
  const double el2 = axnl * axnl + aynl * aynl;
  const double pl = am * (1.0 - el2);
  if (pl < 0.0) return failed(Sgp4Error::kSemiLatusRectum);
  // Short-period periodics.
  const double rl = am * (1.0 - ecose);
  const double rdotl = std::sqrt(am) * esine / rl;
  const double rvdotl = std::sqrt(pl) / rl;
  const double betal = std::sqrt(1.0 - el2);
  temp = esine / (1.0 + betal);
  const double sinu = am / rl * (ks.s - aynl - axnl * temp);
  const double cosu = am / rl * (ks.c - axnl + aynl * temp);
  const double sin2u = (cosu + cosu) * sinu;
  const double cos2u = 1.0 - 2.0 * sinu * sinu;
  temp = 1.0 / pl;
  const double temp1 = 0.5 * k_.j2 * temp;
  const double temp2 = temp1 * temp;
  const double mrt = rl * (1.0 - 1.5 * temp2 * betal * c.con41) + 0.5 * temp1 * c.x1mth2 * cos2u;
  // su = atan2(sinu, cosu) + dsu and xinc = inclp + dinc, both corrections below 1e-3 rad
  // (temp2 <= 0.5 J2 / pl^2 < 5.5e-4 for pl >= 1 Earth radius): their sines and cosines by
  // rotation of the unit (sinu, cosu) and of (sinip, cosip).
  const SinCos su = angle_plus(sinu, cosu, -0.25 * temp2 * c.x7thm1 * sin2u);
  const double dinc = 1.5 * temp2 * cosip * sinip * cos2u;
  const SinCos inc = sincos_plus({sinip, cosip}, p.inclp + dinc, dinc);
  const double xnode = p.nodep + 1.5 * temp2 * cosip * sin2u;
  const double mvt = rdotl - nm * temp1 * c.x1mth2 * sin2u / k_.xke_per_min;
  const double rvdot = rvdotl + nm * temp1 * (c.x1mth2 * cos2u + 1.5 * c.con41) / k_.xke_per_min;
  // Orientation vectors U (position direction) and V.
  const double sinsu = su.s, cossu = su.c;
  const double snod = std::sin(xnode), cnod = std::cos(xnode);
  const double sini = inc.s, cosi = inc.c;
  const double xmx = -snod * cosi, xmy = cnod * cosi;
  const Eigen::Vector3d uv(xmx * sinsu + cnod * cossu, xmy * sinsu + snod * cossu, sini * sinsu);
  const Eigen::Vector3d vv(xmx * cossu - cnod * sinsu, xmy * cossu - snod * sinsu, sini * cossu);
  const double vkmpersec = k_.radius_km * k_.xke_per_min / 60.0;
  const double mr_km = mrt * k_.radius_km;
  Sgp4State s;
  for (int i = 0; i < 3; ++i) {
    s.r_teme_m[i] = (mr_km * uv[i]) * 1000.0;
    s.v_teme_mps[i] = ((mvt * uv[i] + rvdot * vv[i]) * vkmpersec) * 1000.0;
  }
  s.error = mrt < 1.0 ? Sgp4Error::kDecayed : Sgp4Error::kNone;
  return s;
}

}  // namespace evade::sgp4
