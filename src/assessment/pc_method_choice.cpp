// Usage checks and the 2D -> 3D-Nc -> Monte Carlo escalation
// (include/evade/assessment/pc_method_choice.hpp gives the source and the indicators).
#include "evade/assessment/pc_method_choice.hpp"

#include "evade/assessment/encounter_2d.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>

#include <Eigen/Eigenvalues>

#include "evade/core/erfc_inverse.hpp"
#include "evade/dynamics/kepler_propagator.hpp"

namespace evade::assessment {
namespace {

UsageFlag flag(const std::string& name, double value, double threshold, const std::string& what) {
  UsageFlag f{name, value, threshold, value > threshold, what};
  return f;
}

// The first local maximum of the mean relative distance from t = 0 in direction sign, within
// bound_s; bound_s when there is none.
double distance_maximum(const KeplerOrbit& o1, const KeplerOrbit& o2, double sign, double bound_s) {
  constexpr int kSteps = 720;  // 1/720 of the bound: 0.5 deg of the orbit
  const double h = bound_s / kSteps;
  auto d = [&](double t) { return (o2.state_at(t).r_eci_m - o1.state_at(t).r_eci_m).norm(); };
  double prev = d(0.0), cur = d(sign * h);
  for (int i = 2; i <= kSteps; ++i) {
    const double next = d(sign * i * h);
    if (cur >= prev && cur > next) return sign * (i - 1) * h;
    prev = cur;
    cur = next;
  }
  return sign * bound_s;
}

}  // namespace

std::vector<UsageFlag> usage_2d(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                                const EarthModel& earth) {
  // The flight form's figures (encounter_2d.hpp: usage_2d_values), named here.
  const Usage2dValues u = usage_2d_values(
      a.at_tca[0].state, a.at_tca[0].cov_eci.block<3, 3>(0, 0), a.at_tca[1].state,
      a.at_tca[1].cov_eci.block<3, 3>(0, 0), a.min_position_eigenvalue_m2[0],
      a.min_position_eigenvalue_m2[1], hbr_m,
      std::sqrt(2.0) * erfc_inverse(cfg.conj_duration_gamma), earth);
  std::vector<UsageFlag> f;
  if (u.zero_speed) {  // zero relative velocity: the 2D method does not apply at all
    f.push_back(flag("extended", 1.0, cfg.pc2d_extended_cutoff,
                     "relative speed is zero: the conjunction has no duration bound"));
    f.push_back(flag("offset", 1.0, cfg.pc2d_offset_cutoff,
                     "relative speed is zero: no time of closest approach"));
    return f;
  }
  f.push_back(flag("extended", u.extended, cfg.pc2d_extended_cutoff,
                   "conjunction duration / shorter orbital period"));
  f.push_back(flag("offset", u.offset, cfg.pc2d_offset_cutoff,
                   "farthest conjunction bound from TCA / shorter orbital period"));
  f.push_back(flag("npd", u.npd ? 1.0 : 0.0, 0.0,
                   "a position covariance has an eigenvalue <= 0 (repaired before the Pc)"));
  f.push_back(flag("short_term", a.short_term.valid ? 0.0 : 1.0, 0.0,
                   a.short_term.valid ? "Chan/Alfano short-term check holds" : a.short_term.reason));
  return f;
}

Nc3dSpans nc3d_spans(const Assessment& a, const Nc3dResult& nc, const EarthModel& earth) {
  const KeplerOrbit o1(a.at_tca[0].state, earth.mu_m3ps2), o2(a.at_tca[1].state, earth.mu_m3ps2);
  const double bound = std::min(shorter_period_s(a, earth), 1e7);
  Nc3dSpans s;
  s.segment_begin_s = distance_maximum(o1, o2, -1.0, bound);
  s.segment_end_s = distance_maximum(o1, o2, 1.0, bound);
  s.conj_begin_s = std::max(nc.conj_begin_s, s.segment_begin_s);
  s.conj_end_s = std::min(nc.conj_end_s, s.segment_end_s);
  return s;
}

std::vector<UsageFlag> usage_3d_nc(const Nc3dResult& nc, const Nc3dSpans& s,
                                   const AssessConfig& cfg) {
  std::vector<UsageFlag> f;
  const double seg = s.segment_end_s - s.segment_begin_s;
  f.push_back(flag("converged", nc.converged ? 0.0 : 1.0, 0.0,
                   nc.converged ? "3D-Nc integral converged" : "3D-Nc: " + nc.failure));
  f.push_back(flag("extended", (s.conj_end_s - s.conj_begin_s) / seg, cfg.nc3d_extended_cutoff,
                   "conjunction span / encounter segment between relative-distance maxima"));
  f.push_back(flag("offset",
                   std::max(s.conj_begin_s / s.segment_begin_s, s.conj_end_s / s.segment_end_s),
                   cfg.nc3d_offset_cutoff,
                   "conjunction bound / segment bound on the same side of TCA"));
  return f;
}

namespace {

bool any_violated(const std::vector<UsageFlag>& f) {
  return std::any_of(f.begin(), f.end(), [](const UsageFlag& u) { return u.violated; });
}

Nc3dResult nc3d_of(const Assessment& a, const std::array<Mat6, 2>& cov, double hbr_m,
                   const Nc3dOptions& o, const EarthModel& earth) {
  return pc_3d_nc(a.at_tca[0].state, cov[0], a.at_tca[1].state, cov[1], hbr_m, earth.mu_m3ps2, o);
}

PcStep step_of(PcMethod m, double pc, std::vector<UsageFlag> usage) {
  PcStep s;
  s.value = PcValue{m, pc, {}};
  s.checks_hold = !any_violated(usage);
  s.usage = std::move(usage);
  return s;
}

// The reason of a recommendation: the steps that failed their checks (failed) or could not
// run without 6x6 covariances (skipped), then the recommended one (its checks hold, or it is
// the last resort without checks). "no 2D usage check fails"; "a 2D usage check fails; no
// 3D-Nc check fails"; "a 2D usage check and a 3D-Nc check fail"; "a 2D usage check fails and
// 3D-Nc needs 6x6 covariances".
std::string reason(const std::vector<const PcMethodRow*>& failed,
                   const std::vector<const PcMethodRow*>& skipped, const PcMethodRow& chosen) {
  auto check = [](const PcMethodRow* r) { return std::string(r->label) + " " + r->check_noun; };
  if (chosen.check_noun != nullptr) {
    std::string t;
    for (const PcMethodRow* r : failed) t += "a " + check(r) + " fails; ";
    return t + "no " + check(&chosen) + " fails";
  }
  std::string t;
  for (std::size_t i = 0; i < failed.size(); ++i) t += (i == 0 ? "a " : " and a ") + check(failed[i]);
  if (skipped.empty()) return t + (failed.size() > 1 ? " fail" : " fails");
  t += " fails";
  for (const PcMethodRow* r : skipped) t += std::string(" and ") + r->label + " needs 6x6 covariances";
  return t;
}

}  // namespace

const PcStep* PcChoice::step(PcMethod m) const {
  for (const PcStep& s : steps) {
    if (s.value.method == m) return &s;
  }
  return nullptr;
}

PcStep escalate_2d(const PcStepInput& in, PcChoice* /*c*/) {
  return step_of(PcMethod::k2d, pc_of(in.a.plane_pc, PcMethod::k2d),
                 usage_2d(in.a, in.hbr_m, in.cfg, in.earth));
}

// 3D-Nc from the covariances as given (a slightly NPD one is used as it is, as CARA does), or
// from the repaired ones when 3D-Nc refuses those; a refusal of both fails the check
// "converged" with the reason.
PcStep escalate_3d_nc(const PcStepInput& in, PcChoice* c) {
  const Assessment& a = in.a;
  Nc3dOptions o;
  o.window_s = in.cfg.window_s;
  o.gamma = in.cfg.conj_duration_gamma;
  try {
    try {
      c->nc3d = nc3d_of(a, a.cov_unrepaired_eci, in.hbr_m, o, in.earth);
    } catch (const std::invalid_argument&) {
      c->nc3d = nc3d_of(a, {a.at_tca[0].cov_eci, a.at_tca[1].cov_eci}, in.hbr_m, o, in.earth);
    }
  } catch (const std::exception& e) {
    Nc3dResult failed;
    failed.pc = std::numeric_limits<double>::quiet_NaN();
    failed.failure = e.what();
    c->nc3d = failed;
  }
  c->spans = nc3d_spans(a, *c->nc3d, in.earth);
  return step_of(PcMethod::k3dNc, c->nc3d->pc, usage_3d_nc(*c->nc3d, *c->spans, in.cfg));
}

PcStep escalate_mc(const PcStepInput& in, PcChoice* c) {
  const Assessment& a = in.a;
  const AssessConfig& cfg = in.cfg;
  MonteCarloOptions mc;
  mc.window_s = cfg.window_s > 0.0 ? cfg.window_s : mc_window_s(a, in.hbr_m, cfg, in.earth);
  if (c->nc3d && cfg.window_s <= 0.0) mc.window_s = std::max(-c->nc3d->t_begin_s, c->nc3d->t_end_s);
  mc.samples = cfg.mc_max_samples;
  mc.target_rel_accuracy = cfg.mc_target_rel_accuracy;
  mc.threads = in.exec.threads;
  mc.wave_blocks = in.exec.wave_blocks;
  mc.j2 = cfg.mc_j2;
  mc.seed = 1;
  // A Monte Carlo the caller asked for (in the assessment) serves; else one is run.
  c->mc = a.mc ? *a.mc : pc_monte_carlo(mc_encounter(a, in.hbr_m, in.earth), mc, in.exec.runner);
  PcStep s = step_of(PcMethod::kMc, c->mc->pc, {});
  s.value = monte_carlo_value(*c->mc);
  return s;
}

PcValue monte_carlo_value(const MonteCarloResult& mc) {
  return {PcMethod::kMc, mc.pc, {{"low", mc.pc_low}, {"high", mc.pc_high}}};
}

PcChoice choose_pc(const Assessment& a, double hbr_m, const AssessConfig& cfg,
                   const EarthModel& earth, bool six_by_six, const McExecution& exec,
                   bool every_method) {
  const PcStepInput in{a, hbr_m, cfg, earth, exec};
  PcChoice c;
  std::vector<const PcMethodRow*> failed, skipped;
  bool chosen = false;
  for (const PcMethodRow& row : pc_methods()) {
    if (row.escalate == nullptr || (chosen && !(every_method && row.every_method))) continue;
    if (row.needs_six_by_six && !six_by_six) {
      if (!chosen) skipped.push_back(&row);
      continue;
    }
    c.steps.push_back(row.escalate(in, &c));
    if (chosen) continue;
    if (!c.steps.back().checks_hold) {
      failed.push_back(&row);
      continue;
    }
    chosen = true;
    c.pc = c.steps.back().value.pc;
    c.method = row.name;
    c.why = reason(failed, skipped, row);
  }
  return c;
}

}  // namespace evade::assessment
