// The case of a conjunction HIL run (conjunction_hil.hpp; docs/AUTONOMY.md AUT-11): the primary
// on a circular orbit, the secondary placed at TCA miss_m off the primary, perpendicular to the
// relative velocity (so TCA is the closest approach), crossing at crossing_deg, and carried
// back to t = 0 under the same truth (two-body + J2 is time-reversible: the state with its
// velocity reversed, propagated forward, reversed again); the ground's CDMs from the truth at
// TCA (commands::cdm_from_event) read back as `evade conjunction` reads them.
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/commands/cdm_from_event.hpp"
#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/core/epoch.hpp"
#include "evade/hil/conjunction_hil.hpp"

namespace evade::hil {
namespace {

using Cfg = ConjunctionHilConfig;
constexpr double kDeg = M_PI / 180.0;
constexpr std::int64_t kEpochUnixS = 1767225600;  // 2026-01-01T00:00:00Z: the run's t = 0

const Param<Cfg> kRows[] = {
    with_flag(EVADE_PARAM_REAL(Cfg, altitude_m, "m", 200e3, 2000e3, false,
                               "the primary's circular orbit above the equatorial radius (LEO)"), "--altitude-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, inclination_deg, "deg", 0.0, 180.0, false, "the primary's inclination"),
              "--inclination-deg"),
    with_flag(EVADE_PARAM_REAL(Cfg, orbits_to_tca, "-", 0.5, 5.0, false,
                               "TCA this many of the primary's periods after the run starts"), "--orbits-to-tca"),
    with_flag(EVADE_PARAM_REAL(Cfg, miss_m, "m", 0.0, 20000.0, false, "the truth's miss at TCA without a burn"),
              "--miss-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, crossing_deg, "deg", 10.0, 170.0, false,
                               "the angle between the two velocities at TCA"), "--crossing-deg"),
    with_flag(EVADE_PARAM_REAL(Cfg, hbr_m, "m", 0.0, 100.0, true, "the combined hard-body radius"), "--hbr-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, own_sigma_m, "m", 0.0, 10000.0, true,
                               "the primary's radial position sigma in the CDM (along-track 3x, normal 0.5x)"),
              "--own-sigma-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, other_sigma_m, "m", 0.0, 10000.0, true,
                               "the secondary's radial position sigma in the CDM (same shape)"), "--other-sigma-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, first_cdm_s, "s", 0.0, 86400.0, false,
                               "the first CDM is sent this long after the run starts"), "--first-cdm-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, update_lead_s, "s", 600.0, 86400.0, false,
                               "run update: the new version is sent this long before TCA"),
              "--update-lead-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, update_offset_m, "m", 0.0, 100000.0, false,
                               "run update: the first CDM's secondary this far off its true path"),
              "--update-offset-m"),
    with_flag(EVADE_PARAM_REAL(Cfg, update_veto_deadline_before_tca_s, "s", 0.0, 86400.0, false,
                               "run update: the new version's veto deadline before TCA"),
              "--update-veto-deadline-before-tca-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, after_tca_s, "s", 20.0, 3600.0, false, "the run ends this long after TCA"),
              "--after-tca-s"),
    with_flag(EVADE_PARAM_REAL(Cfg, rate_hz, "Hz", 0.0, 1000.0, true,
                               "the exchange rate: the node's guidance.rate_hz"), "--rate-hz"),
};

// RTN covariance of the case's shape: position sigmas (s, 3s, s/2), velocities the same times the
// mean motion (the drift of an orbit-determination error over a radian of orbit).
Mat6 cov_rtn(double sigma_m, double n_radps) {
  Vec6 s;
  s << sigma_m, 3.0 * sigma_m, 0.5 * sigma_m, sigma_m * n_radps, 3.0 * sigma_m * n_radps,
      0.5 * sigma_m * n_radps;
  return s.cwiseProduct(s).asDiagonal();
}

// The two objects: the primary at t = 0, the secondary at TCA from the primary at TCA.
void place_objects(ConjunctionHilCase* c) {
  const Cfg& g = c->config;
  const EarthModel earth = kEarthDefault;
  const double a = earth.re_m + g.altitude_m;
  const double v = std::sqrt(earth.mu_m3ps2 / a);
  const double inc = g.inclination_deg * kDeg;
  c->sim.satellite0 = {Vec3(a, 0.0, 0.0), Vec3(0.0, v * std::cos(inc), v * std::sin(inc))};
  c->tca_s = std::round(g.orbits_to_tca * 2.0 * M_PI * std::sqrt(a * a * a / earth.mu_m3ps2));
  c->sim.other0 = c->sim.satellite0;
  StateEci unused;
  sim::propagate_unforced(c->sim, c->tca_s, &c->own_tca, &unused);
  const Vec3 r_hat = c->own_tca.r_eci_m.normalized();
  const Vec3 v2 = Eigen::AngleAxisd(g.crossing_deg * kDeg, r_hat) * c->own_tca.v_eci_mps;
  const Vec3 u = (v2 - c->own_tca.v_eci_mps).normalized();
  const Vec3 d = (r_hat - r_hat.dot(u) * u).normalized();  // perpendicular to the relative velocity
  c->other_tca = {c->own_tca.r_eci_m + g.miss_m * d, v2};
  sim::PlanRunConfig back = c->sim;
  back.other0 = {c->other_tca.r_eci_m, -c->other_tca.v_eci_mps};
  StateEci other_back;
  sim::propagate_unforced(back, c->tca_s, &unused, &other_back);
  c->sim.other0 = {other_back.r_eci_m, -other_back.v_eci_mps};
}

// One CDM of the pair at the case's TCA with the secondary at other_tca, sent at t_send_s.
HilCdm make_cdm(const ConjunctionHilCase& c, const StateEci& other_tca, double t_send_s, int n,
                const std::vector<ParamValue>& uplink_settings) {
  const Cfg& g = c.config;
  const double n_radps = c.own_tca.v_eci_mps.norm() / c.own_tca.r_eci_m.norm();
  commands::ScreeningEvent ev;
  ev.obj[0] = {"EVADE-1", "SATCAT", "EVADE-1", "", c.own_tca, cov_rtn(g.own_sigma_m, n_radps),
               "the HIL case's primary covariance", 0.0, "the simulator's truth at TCA"};
  ev.obj[1] = {"DEBRIS-1", "SATCAT", "DEBRIS-1", "", other_tca, cov_rtn(g.other_sigma_m, n_radps),
               "the HIL case's secondary covariance", 0.0,
               n == 1 && c.run == HilRun::kUpdate ? "stale tracking: off the truth by hil.update_offset_m"
                                                  : "the simulator's truth at TCA"};
  ev.tca_utc_j2000_s = seconds_since_j2000_from_unix_utime(c.sim.utime0_us) + c.tca_s;
  ev.miss_m = (other_tca.r_eci_m - c.own_tca.r_eci_m).norm();
  ev.rel_speed_mps = (other_tca.v_eci_mps - c.own_tca.v_eci_mps).norm();
  ev.screen_start_utc_j2000_s = seconds_since_j2000_from_unix_utime(c.sim.utime0_us) + t_send_s;
  ev.screen_stop_utc_j2000_s = ev.tca_utc_j2000_s + 86400.0;
  commands::EventCdmOptions opt;
  opt.message_id = std::string("EVADE-HIL-") + hil_run_name(c.run) + "-" + std::to_string(n);
  opt.creation_utc_j2000_s = ev.screen_start_utc_j2000_s;
  opt.hbr_m = g.hbr_m;
  opt.hbr_source = "hil.hbr_m";
  const commands::EventCdm cdm = commands::cdm_from_event(ev, opt);
  HilCdm h;
  h.t_send_s = t_send_s;
  h.file_name = opt.message_id + ".cdm";
  h.text = ccsds::write_cdm_kvn(cdm.cdm);
  h.miss_m = ev.miss_m;
  h.pc = cdm.pc.value_or(0.0);
  h.pc_method = cdm.pc_method;
  config::Scenario sc = config::Scenario::empty("hil");
  for (const ParamValue& v : uplink_settings) sc.set_value(v);
  const std::int64_t now_us = c.sim.utime0_us + static_cast<std::int64_t>(std::llround(t_send_s * 1e6));
  h.uplink = commands::read_conjunction_uplink(sc, h.text, h.file_name, g.hbr_m, now_us);
  return h;
}

// The update run's first CDM: the secondary off its truth across the relative velocity, in
// the encounter plane (the same TCA, a larger miss).
StateEci stale_secondary(const ConjunctionHilCase& c) {
  const Vec3 u = (c.other_tca.v_eci_mps - c.own_tca.v_eci_mps).normalized();
  const Vec3 d = (c.other_tca.r_eci_m - c.own_tca.r_eci_m);
  Vec3 across = u.cross(d.norm() > 0.0 ? d.normalized() : c.own_tca.r_eci_m.normalized());
  across.normalize();
  return {c.other_tca.r_eci_m + c.config.update_offset_m * across, c.other_tca.v_eci_mps};
}

}  // namespace

ParamTable<ConjunctionHilConfig> conjunction_hil_params() noexcept { return make_param_table(kRows); }

bool parse_hil_run(const std::string& name, HilRun* out) noexcept {
  for (const HilRun r : {HilRun::kBurn, HilRun::kVeto, HilRun::kUpdate}) {
    if (name == hil_run_name(r)) {
      *out = r;
      return true;
    }
  }
  return false;
}

const char* hil_run_name(HilRun r) noexcept {
  switch (r) {
    case HilRun::kBurn: return "burn";
    case HilRun::kVeto: return "veto";
    case HilRun::kUpdate: return "update";
  }
  return "unknown";
}

ConjunctionHilCase conjunction_hil_case(HilRun run, const std::vector<ParamValue>& settings) {
  ConjunctionHilCase c;
  c.run = run;
  std::vector<ParamValue> uplink;
  config::Scenario sc = config::Scenario::empty("hil");
  for (const ParamValue& v : settings) {
    if (v.key.rfind("uplink.", 0) == 0) uplink.push_back(v);
    else sc.set_value(v);
  }
  config::read_params(sc, "hil.", conjunction_hil_params(), &c.config);
  sc.check_all_used();
  const Cfg& g = c.config;
  c.sim.gravity = GravityModel::kTwoBodyJ2;
  c.sim.rate_hz = g.rate_hz;
  c.sim.utime0_us = kEpochUnixS * 1000000;
  c.sim.actuator.max_accel_mps2 = 100.0;  // the node's max_accel_mps2 limits the command
  place_objects(&c);
  const double last_cdm_s = run == HilRun::kUpdate ? c.tca_s - g.update_lead_s : c.tca_s;
  if (!(g.first_cdm_s < last_cdm_s))
    throw std::invalid_argument(std::string("hil.first_cdm_s must be before TCA") +
                                (run == HilRun::kUpdate ? " minus hil.update_lead_s" : "") +
                                " (TCA is " + param_value_text(c.tca_s) + " s into the run)");
  c.sim.duration_s = c.tca_s + g.after_tca_s;
  // Every cycle within 20 s of TCA: the burned TCA moves by well under a second (hil_closest_approach).
  const long n = std::lround(40.0 * g.rate_hz);
  for (long k = 0; k <= n; ++k) c.sim.sample_t_s.push_back(c.tca_s - 20.0 + static_cast<double>(k) / g.rate_hz);
  c.veto = run == HilRun::kVeto;
  if (run != HilRun::kUpdate) {
    c.cdms.push_back(make_cdm(c, c.other_tca, g.first_cdm_s, 1, uplink));
    return c;
  }
  c.cdms.push_back(make_cdm(c, stale_secondary(c), g.first_cdm_s, 1, uplink));
  uplink.push_back({"uplink.veto_deadline_before_tca_s", g.update_veto_deadline_before_tca_s});
  c.cdms.push_back(make_cdm(c, c.other_tca, c.tca_s - g.update_lead_s, 2, uplink));
  return c;
}

}  // namespace evade::hil
