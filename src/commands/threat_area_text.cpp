// The human text of `evade plan threat-area` (threat_area_command.hpp): the chaser's cost at
// t0, the evasive burn (paper 001, Yu Dateng, Wang Hua, Sun Fuyu 2017, sec. 3.1 eq. 4: one
// impulse at t0 of magnitude V_E, pitch α and yaw θ in the target's VVLH frame; its Δv in
// VVLH and in RSW), the threat arc and its intervals (seconds after t0, the scenario's
// t = 0), the search certificate, the eliminating burn (sec. 4.2) and the sweep rows
// (Fig. 8, Fig. 4) when asked for.
#include <cstdio>
#include <string>

#include "evade/commands/threat_area_command.hpp"

#include "evade/core/text_format.hpp"

namespace evade::commands {
namespace {

std::string vec_text(const Vec3& v) {
  return format_text("[%+.4f, %+.4f, %+.4f] m/s", v.x(), v.y(), v.z());
}

std::string intervals_text(const threat::ThreatArea& a) {
  if (a.intervals.empty()) return "none";
  std::string s;
  for (const threat::ThreatInterval& iv : a.intervals) {
    s += format_text("%s[%.2f, %.2f]", s.empty() ? "" : ", ", iv.start_s, iv.end_s);
  }
  return s;
}

// The burn of one search: direction and Δv, both at t0.
std::string burn_text(const char* label, const threat::EvasionResult& r) {
  return format_text("  %s at t0: alpha (pitch) %.4f rad, theta (yaw) %.4f rad in VVLH;\n"
                "    dv_vvlh %s, dv_rsw %s\n",
                label, r.alpha_rad, r.theta_rad, vec_text(r.dv_vvlh_mps).c_str(),
                vec_text(r.dv_rsw_mps).c_str());
}

std::string certificate_text(const threat::SearchCertificate& c) {
  if (c.grid_evaluations <= 0 || c.bound_cells <= 0) return "";
  return format_text("  search: sweep %ld + BOBYQA %ld evaluations; no direction's arc is below "
                "%.2f s (%ld cells bounded, %s)\n",
                c.grid_evaluations, c.local_evaluations, c.lower_bound_arc_s, c.bound_cells,
                c.certified ? "certified" : "not certified within the tolerance");
}

std::string elimination_text(const threat::ThreatStudy& s) {
  if (!s.elimination) return "";
  const threat::EliminationResult& e = *s.elimination;
  return format_text("  eliminating V_E = %.3f m/s (%.1f%% of dv_max; t0 bound %.3f m/s; "
                "%.3f m/s still threatened)\n",
                e.eliminating_dv_mps, 100.0 * s.eliminating_to_dv_max_ratio, s.t0_bound_mps,
                e.threatened_dv_mps) +
         burn_text("eliminating burn", e.best);
}

std::string sweep_dv_text(const threat::ThreatStudy& s) {
  std::string t;
  if (!s.sweep_dv.empty()) t += "  sweep of V_E (Fig. 8; alpha, theta in VVLH):\n";
  for (const threat::BurnSweepRow& row : s.sweep_dv) {
    const threat::EvasionResult& q = row.evasion;
    t += format_text("    V_E = %8.3f m/s: arc %9.2f s (%7.3f deg), alpha %.4f rad, theta %.4f rad\n",
                q.dv_mps, q.area.arc_s, q.area.arc_deg, q.alpha_rad, q.theta_rad);
  }
  return t;
}

std::string sweep_transfer_text(const threat::ThreatStudy& s) {
  std::string t;
  if (!s.sweep_transfer.empty()) t += "  sweep of the transfer time (Fig. 4):\n";
  for (const threat::TransferStudyRow& r : s.sweep_transfer) {
    t += format_text("    dT = %7.1f s: J(t0) = %.3f m/s (2/3/4 impulses %.3f/%.3f/%.3f m/s), "
                "t0 bound %.3f m/s",
                r.dt_transfer_s, r.j_t0_mps, r.cost_t0_mps[0], r.cost_t0_mps[1],
                r.cost_t0_mps[2], r.t0_bound_mps);
    if (r.elimination) t += format_text(", eliminating V_E %.3f m/s", r.elimination->eliminating_dv_mps);
    t += '\n';
  }
  return t;
}

}  // namespace

std::string to_text(const ThreatAreaResult& r) {
  const threat::ThreatScenario& in = r.scenario;
  const threat::ThreatStudy& s = r.study;
  const threat::EvasionResult& e = s.evasion;
  std::string t = format_text("threat area (paper 001): dT = %.1f s, %d impulses, dv_max = %.1f m/s\n",
                         in.threat.transfer_s, in.threat.impulses, in.threat.dv_max_mps);
  t += format_text("  chaser cost at t0 without evasion: %.3f m/s (dv_max - cost = %.3f m/s)\n",
              s.chaser_cost_t0_mps, s.t0_bound_mps);
  t += format_text("  V_E = %.3f m/s: arc %.2f s (%.3f deg), %ld evaluations, %.3f s wall\n",
              e.dv_mps, e.area.arc_s, e.area.arc_deg, e.evaluations, s.runtime_s);
  t += burn_text("evasive burn", e);
  t += "  threat intervals (s after t0): " + intervals_text(e.area) + "\n";
  t += certificate_text(e.certificate);
  t += elimination_text(s);
  t += sweep_dv_text(s);
  t += sweep_transfer_text(s);
  return t;
}

}  // namespace evade::commands
