// The ground's review of a proposed burn (docs/AUTONOMY.md AUT-10): a catalog object placed
// where the burn sends the spacecraft (an SGP4 element set fitted to the burned orbit's state
// half an orbit after the burn, crossing it at 60 degrees) makes the review recommend a veto;
// the same object placed on the orbit without the burn (the burn takes the spacecraft away
// from it) and a catalog of distant objects let the burn fly; a bad proposal is an error
// naming its key.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include <Eigen/Dense>
#include <gtest/gtest.h>

#include "evade/commands/cam_review_command.hpp"
#include "evade/conjunction/own_orbit_motion.hpp"
#include "evade/core/constants.hpp"
#include "evade/core/epoch.hpp"
#include "evade/dynamics/orbit_propagator.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"

namespace evade::commands {
namespace {

constexpr double kUnixJ2000S = 946728000.0;
constexpr double kBurnBeforeTcaS = 5400.0;
constexpr double kMeetAfterBurnS = 2900.0;  // about half an orbit: the burn's largest radial offset

double tca_j2000_s() { return seconds_since_j2000_from_calendar(parse_calendar_utc("2026-11-24T12:00:00")); }

// A circular orbit of radius 7000 km at 51.6 degrees, at TCA (J2000).
StateEci own_at_tca() {
  const double r = 7.0e6, v = std::sqrt(kEarthDefault.mu_m3ps2 / r), inc = 51.6 * kPi / 180.0;
  return {Vec3(r, 0.0, 0.0), Vec3(0.0, v * std::cos(inc), v * std::sin(inc))};
}

void set_epoch(double j2000_s, sgp4::MeanElements* m) {
  const double jan1 = seconds_since_j2000_from_calendar(parse_calendar_utc("2026-01-01T00:00:00"));
  m->epoch_year = 2026;
  m->epoch_day_of_year = 1.0 + (j2000_s - jan1) / 86400.0;
}

// Classical elements of a TEME state under WGS-72 (the first guess of the fit).
std::array<double, 6> osculating(const Vec3& r, const Vec3& v) {
  const double mu = 3.986008e14, rn = r.norm();
  const Vec3 h = r.cross(v), node = Vec3::UnitZ().cross(h);
  const Vec3 ev = ((v.squaredNorm() - mu / rn) * r - r.dot(v) * v) / mu;
  const double e = ev.norm(), a = 1.0 / (2.0 / rn - v.squaredNorm() / mu);
  const double inc = std::acos(h.z() / h.norm());
  double raan = std::atan2(node.y(), node.x());
  double argp = std::acos(node.dot(ev) / (node.norm() * e));
  if (ev.z() < 0.0) argp = 2.0 * kPi - argp;
  double nu = std::acos(ev.dot(r) / (e * rn));
  if (r.dot(v) < 0.0) nu = 2.0 * kPi - nu;
  const double ea = 2.0 * std::atan(std::sqrt((1.0 - e) / (1.0 + e)) * std::tan(nu / 2.0));
  const double m = ea - e * std::sin(ea);
  const double n_revpday = std::sqrt(mu / (a * a * a)) * 86400.0 / (2.0 * kPi);
  const double deg = 180.0 / kPi;
  return {n_revpday, e, inc * deg, std::fmod(raan * deg + 360.0, 360.0), argp * deg, std::fmod(m * deg + 360.0, 360.0)};
}

sgp4::MeanElements with(sgp4::MeanElements m, const std::array<double, 6>& x) {
  m.mean_motion_revpday = x[0];
  m.eccentricity = x[1];
  m.inclination_deg = x[2];
  m.raan_deg = x[3];
  m.arg_perigee_deg = x[4];
  m.mean_anomaly_deg = x[5];
  return m;
}

Eigen::Matrix<double, 6, 1> residual(const sgp4::MeanElements& m, const Vec3& r, const Vec3& v) {
  const sgp4::Sgp4State s = sgp4::Sgp4Propagator(m).propagate_min(0.0);
  Eigen::Matrix<double, 6, 1> f;
  f << s.r_teme_m - r, (s.v_teme_mps - v) * 1000.0;  // 1 mm/s weighs as 1 m
  return f;
}

// Mean elements at epoch j2000_s whose SGP4 state there is (r, v) in TEME: Newton on the six
// elements from the osculating ones, the Jacobian by central differences.
sgp4::MeanElements fit_elements(double j2000_s, const Vec3& r, const Vec3& v, long norad) {
  sgp4::MeanElements m;
  m.norad_id = norad;
  m.name = "OBJ" + std::to_string(norad);
  set_epoch(j2000_s, &m);
  std::array<double, 6> x = osculating(r, v);
  const std::array<double, 6> step = {1e-6, 1e-7, 1e-6, 1e-6, 1e-6, 1e-6};
  for (int it = 0; it < 20; ++it) {
    const Eigen::Matrix<double, 6, 1> f = residual(with(m, x), r, v);
    if (f.norm() < 1e-3) break;
    Eigen::Matrix<double, 6, 6> jac;
    for (int k = 0; k < 6; ++k) {
      std::array<double, 6> hi = x, lo = x;
      hi[k] += step[k];
      lo[k] -= step[k];
      jac.col(k) = (residual(with(m, hi), r, v) - residual(with(m, lo), r, v)) / (2.0 * step[k]);
    }
    const Eigen::Matrix<double, 6, 1> dx = jac.colPivHouseholderQr().solve(-f);
    for (int k = 0; k < 6; ++k) x[k] += dx(k);
  }
  return with(m, x);
}

struct Case {
  CamReviewRequest req;
  double burn_j2000_s = 0.0;
};

Case base_case() {
  Case c;
  c.req.conjunction.obj[0].state = own_at_tca();
  c.req.conjunction.hbr_m = 20.0;
  c.req.tca_j2000_s = tca_j2000_s();
  c.burn_j2000_s = c.req.tca_j2000_s - kBurnBeforeTcaS;
  c.req.proposal.event_id = 7;
  c.req.proposal.version = 1;
  c.req.proposal.proposal_id = 3;
  c.req.proposal.burn_utime = static_cast<std::int64_t>(std::llround((c.burn_j2000_s + kUnixJ2000S) * 1e6));
  c.req.span_s = 2.0 * kBurnBeforeTcaS;
  c.req.threads = 2;
  return c;
}

// The own spacecraft in TEME kMeetAfterBurnS after the burn, with or without it.
StateEci own_teme_at_meeting(const Case& c, bool burned) {
  StateEci s = propagate_orbit(own_at_tca(), -kBurnBeforeTcaS, GravityModel::kTwoBodyJ2, kEarthDefault,
                               AdaptiveOptions::tight());
  s.v_eci_mps += c.req.proposal.dv_eci_mps * (burned ? 1.0 : 0.0);
  const StateEci j = propagate_orbit(s, kMeetAfterBurnS, GravityModel::kTwoBodyJ2, kEarthDefault,
                                     AdaptiveOptions::tight());
  const Eigen::Matrix3d m = sgp4::teme_to_j2000_matrix(c.burn_j2000_s + kMeetAfterBurnS);
  return {m.transpose() * j.r_eci_m, m.transpose() * j.v_eci_mps};
}

// An object meeting s: the same position, the velocity turned 60 degrees about the radial and
// 2 % faster (an eccentric crossing orbit, so that the fit's elements are well defined).
sgp4::MeanElements crosser(const Case& c, const StateEci& s, long norad) {
  const Vec3 v = Eigen::AngleAxisd(60.0 * kPi / 180.0, s.r_eci_m.normalized()) * s.v_eci_mps * 1.02;
  return fit_elements(c.burn_j2000_s + kMeetAfterBurnS, s.r_eci_m, v, norad);
}

// A distant object: a circular orbit at 20 000 km.
sgp4::MeanElements distant(const Case& c) {
  sgp4::MeanElements m;
  m.norad_id = 80009;
  m.name = "FAR";
  set_epoch(c.burn_j2000_s, &m);
  m.mean_motion_revpday = 2.006;
  m.eccentricity = 0.001;
  m.inclination_deg = 55.0;
  return m;
}

const CamReviewEncounter* find(const CamReviewResult& r, long norad) {
  for (const CamReviewEncounter& e : r.encounters)
    if (e.norad_id == norad) return &e;
  return nullptr;
}

TEST(CamReviewCommand, AnObjectWhereTheBurnSendsTheSpacecraftIsAVeto) {
  Case c = base_case();
  c.req.proposal.dv_eci_mps = own_at_tca().v_eci_mps.normalized();  // 1 m/s along track
  const StateEci meet = own_teme_at_meeting(c, true);
  const sgp4::MeanElements b = crosser(c, meet, 80001);
  ASSERT_LT(residual(b, meet.r_eci_m, Eigen::AngleAxisd(60.0 * kPi / 180.0, meet.r_eci_m.normalized()) *
                                          meet.v_eci_mps * 1.02).head<3>().norm(), 0.01);
  c.req.catalog.objects = {b, distant(c)};
  const CamReviewResult r = run_cam_review(c.req);
  EXPECT_EQ(r.verdict, "veto") << r.reason;
  const CamReviewEncounter* e = find(r, 80001);
  ASSERT_NE(e, nullptr);
  EXPECT_TRUE(e->after);
  EXPECT_LT(e->miss_after_m, 1.0) << "the fitted object sits on the burned orbit";
  EXPECT_NEAR(e->tca_after_s, kMeetAfterBurnS, 1e-3);
  EXPECT_TRUE(e->raised);
  EXPECT_GT(e->pc_max_after, c.req.pc_red);
  // Without the burn the spacecraft is kilometres away: a max Pc below the red threshold.
  EXPECT_TRUE(!e->before || e->pc_max_before < c.req.pc_red) << e->miss_before_m;
  EXPECT_EQ(find(r, 80009), nullptr) << "20 000 km away: no close approach";
  EXPECT_EQ(r.objects, 2);
  std::printf("%s", to_text(r).c_str());
}

TEST(CamReviewCommand, AnObjectTheBurnTakesTheSpacecraftAwayFromLetsItFly) {
  Case c = base_case();
  c.req.proposal.dv_eci_mps = own_at_tca().v_eci_mps.normalized();
  c.req.catalog.objects = {crosser(c, own_teme_at_meeting(c, false), 80002), distant(c)};
  const CamReviewResult r = run_cam_review(c.req);
  EXPECT_EQ(r.verdict, "fly") << r.reason;
  const CamReviewEncounter* e = find(r, 80002);
  ASSERT_NE(e, nullptr);
  EXPECT_TRUE(e->before);
  EXPECT_LT(e->miss_before_m, 1.0) << "the object sits on the orbit without the burn";
  EXPECT_FALSE(e->raised);
  EXPECT_LT(e->pc_max_after, e->pc_max_before);
  std::printf("%s", to_text(r).c_str());
}

TEST(CamReviewCommand, TheOwnOrbitBesideTheCatalogIsTheJ2OrbitInTeme) {
  Case c = base_case();
  const StateEci own_burn = propagate_orbit(own_at_tca(), -kBurnBeforeTcaS, GravityModel::kTwoBodyJ2,
                                            kEarthDefault, AdaptiveOptions::tight());
  const sgp4::MeanElements far = distant(c);
  const conjunction::Sgp4Screening s = conjunction::sgp4_screening({far}, [&] {
    conjunction::Sgp4MotionOptions mo;
    mo.span_s = c.req.span_s;
    mo.start_at_latest_epoch = false;
    mo.start_j2000_s = c.burn_j2000_s;
    return mo;
  }());
  const conjunction::OwnOrbitMotion m(own_burn, c.burn_j2000_s, c.req.span_s, kEarthDefault, s.motion);
  ASSERT_EQ(m.size(), 2u);
  const StateEci t = m.state_at(0, kMeetAfterBurnS);
  const StateEci expect = own_teme_at_meeting(c, false);
  EXPECT_LT((t.r_eci_m - expect.r_eci_m).norm(), 1e-3);
  // The velocity is the derivative of the position returned (the frames' rotation included).
  const double h = 0.5;
  const Vec3 diff = (m.state_at(0, kMeetAfterBurnS + h).r_eci_m - m.state_at(0, kMeetAfterBurnS - h).r_eci_m) / (2 * h);
  EXPECT_LT((diff - t.v_eci_mps).norm(), 2e-3) << "central difference error h^2 |r'''| / 6 ~ 1e-3 m/s";
  // The J2 about the J2000 pole seen from the TEME pole: the 0.15 degree between them.
  EXPECT_GT(m.own_sampled_perturbation_mps2(), 1e-6);
  EXPECT_LT(m.own_sampled_perturbation_mps2(), 1e-3);
  EXPECT_EQ(m.state_at(1, 100.0).r_eci_m, s.motion->state_at(0, 100.0).r_eci_m);
}

TEST(CamReviewCommand, ABadProposalOrRequestIsAnErrorNamingIt) {
  nlohmann::json j = to_json(CamReviewProposal{7, 1, 3, 1795521600000000LL, Vec3(0.0, 0.1, 0.0)});
  EXPECT_EQ(cam_review_proposal_from_json(j, "p.json").proposal_id, 3);
  nlohmann::json missing = j;
  missing.erase("burn_utime");
  EXPECT_THROW(
      {
        try {
          (void)cam_review_proposal_from_json(missing, "p.json");
        } catch (const std::invalid_argument& e) {
          EXPECT_NE(std::string(e.what()).find("burn_utime"), std::string::npos);
          throw;
        }
      },
      std::invalid_argument);
  nlohmann::json short_dv = j;
  short_dv["dv_eci_mps"] = {0.0, 0.1};
  EXPECT_THROW((void)cam_review_proposal_from_json(short_dv, "p.json"), std::invalid_argument);
  Case c = base_case();
  c.req.catalog.objects = {distant(c)};
  c.req.proposal.burn_utime += static_cast<std::int64_t>(2 * kBurnBeforeTcaS * 1e6);  // after TCA
  EXPECT_THROW((void)run_cam_review(c.req), std::invalid_argument);
  Case d = base_case();
  d.req.catalog.objects = {distant(d)};
  d.req.span_s = 1000.0;  // ends before TCA
  EXPECT_THROW((void)run_cam_review(d.req), std::invalid_argument);
  EXPECT_EQ(pc_max_circular(10.0, 20.0), 1.0);
  EXPECT_NEAR(pc_max_circular(2000.0, 20.0), 400.0 / (std::exp(1.0) * 4e6), 1e-3 * 400.0 / (std::exp(1.0) * 4e6));
}

}  // namespace
}  // namespace evade::commands
