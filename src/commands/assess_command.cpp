// `evade assess` as a library call (include/evade/commands/assess_command.hpp): the request
// read from a scenario, a CDM or the encounter plane, the assessment (assess.hpp; the Pc
// methods of Foster & Estes 1992, Chan 2008, Alfano 2005 and Alfano 2009), and the result's
// JSON and text forms.
#include "evade/commands/assess_command.hpp"

#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "evade/ccsds/cdm_formats.hpp"
#include "evade/commands/conjunction_input.hpp"
#include "evade/config/json_values.hpp"
#include "evade/config/read_params.hpp"

namespace evade::commands {
namespace {

template <class T>
nlohmann::json optional_json(const std::optional<T>& v) {
  return v ? nlohmann::json(*v) : nlohmann::json(nullptr);
}

// The message's own relative values, beside what is recomputed from its states.
CdmFigures cdm_figures(const ccsds::Cdm& c) {
  auto num = [&](const char* k) {
    const std::string v = ccsds::cdm_value(c.relative, k);
    return v.empty() ? std::optional<double>() : std::optional<double>(std::stod(v));
  };
  CdmFigures f;
  f.message_id = ccsds::cdm_value(c.header, "MESSAGE_ID");
  f.tca_utc = ccsds::cdm_value(c.relative, "TCA");
  f.miss_distance_m = num("MISS_DISTANCE");
  f.relative_speed_mps = num("RELATIVE_SPEED");
  f.collision_probability = num("COLLISION_PROBABILITY");
  const std::string method = ccsds::cdm_value(c.relative, "COLLISION_PROBABILITY_METHOD");
  if (!method.empty()) f.collision_probability_method = method;
  f.unit_notes = ccsds::cdm_unit_notes(c);
  for (const std::string& n : ccsds::cdm_covariance_notes(c)) f.unit_notes.push_back(n);
  return f;
}

AssessResult run_plane(const AssessRequest& req, const assessment::PrincipalEncounter& pe) {
  if (req.mc_samples > 0) throw std::invalid_argument("--mc needs states (--scenario or --cdm)");
  AssessResult r;
  r.source = req.source;
  r.hbr_m = req.plane_hbr_m;
  r.pc_max = assessment::pc_max_alfano(pe, r.hbr_m);
  r.pc_2d = assessment::pc_2d(pe, r.hbr_m).pc;
  r.pc_chan = assessment::pc_chan(pe, r.hbr_m);
  r.miss_m = std::hypot(pe.miss_x_m, pe.miss_y_m);
  r.principal = pe;
  r.pc = r.pc_2d;
  return r;
}

AssessResult run_states(const AssessRequest& req, const assessment::ConjunctionInput& in) {
  std::optional<assessment::MonteCarloOptions> mc;
  if (req.mc_samples > 0) {
    mc = assessment::MonteCarloOptions{};
    mc->samples = req.mc_samples;
    mc->seed = req.mc_seed;
    mc->window_s = req.config.window_s;  // 0: assess() takes mc_window_s
    mc->threads = req.mc_exec.threads;
    mc->wave_blocks = req.mc_exec.wave_blocks;
    mc->j2 = req.config.mc_j2;
  }
  const assessment::Assessment a = assessment::assess(in, req.config, mc, req.mc_exec.runner);
  AssessResult r;
  r.source = req.source;
  r.hbr_m = in.hbr_m;
  r.miss_m = a.plane.miss_3d_m;
  r.rel_speed_mps = a.plane.rel_speed_mps;
  r.principal = a.principal;
  r.pc_2d = a.pc_2d.pc;
  r.pc_2d_abs_error = a.pc_2d.abs_error;
  r.pc_chan = a.pc_chan;
  r.pc_max = a.pc_max;
  r.pc_mc = a.mc;
  r.states = StatesAtTca{a.at_tca,  a.tca_shift_s, a.tca_method, a.covariance_propagation,
                         a.npd,     a.min_eigenvalue, a.plane,   a.short_term};
  if (req.cdm) r.cdm = cdm_figures(*req.cdm);
  const bool six = in.obj[0].has_velocity_cov && in.obj[1].has_velocity_cov;
  r.choice = assessment::choose_pc(a, r.hbr_m, req.config, in.earth, six, req.mc_exec, true);
  r.pc = r.choice->pc;
  r.method = r.choice->method;
  if (!r.pc_mc && r.choice->mc) r.pc_mc = r.choice->mc;
  r.mc_ranks = req.mc_exec.ranks;
  return r;
}

nlohmann::json plane_json(const AssessResult& r) {
  nlohmann::json j;
  if (r.states) {
    j["miss_x_m"] = r.states->plane.miss_m(0);
    j["miss_y_m"] = r.states->plane.miss_m(1);
    j["cov_m2"] = config::matrix_json(r.states->plane.cov_m2);
  }
  const assessment::PrincipalEncounter& pe = r.principal;
  j["principal"] = {{"miss_x_m", pe.miss_x_m}, {"miss_y_m", pe.miss_y_m},
                    {"sigma_x_m", pe.sigma_x_m}, {"sigma_y_m", pe.sigma_y_m}};
  return j;
}

void add_states_json(const StatesAtTca& s, nlohmann::json* j) {
  (*j)["tca"] = {{"shift_s", s.tca_shift_s}, {"method", s.tca_method},
                 {"covariance_propagation", s.covariance_propagation}};
  (*j)["covariance_repaired"] = {s.covariance_repaired[0], s.covariance_repaired[1]};
  (*j)["covariance_min_eigenvalue_m2"] = {s.covariance_min_eigenvalue_m2[0],
                                          s.covariance_min_eigenvalue_m2[1]};
  (*j)["short_term"] = {{"valid", s.short_term.valid},
                        {"encounter_time_s", s.short_term.encounter_time_s},
                        {"period_s", s.short_term.period_s},
                        {"reason", s.short_term.reason}};
}

void add_monte_carlo_json(const assessment::MonteCarloResult& mc, nlohmann::json* j) {
  (*j)["pc_mc"] = mc.pc;
  (*j)["pc_mc_low"] = mc.pc_low;
  (*j)["pc_mc_high"] = mc.pc_high;
  (*j)["mc"] = {{"samples", mc.samples}, {"hits", mc.hits}, {"window_s", mc.window_s},
                {"interval", "Wilson 95 %"}, {"stopped_at_target", mc.stopped_at_target},
                {"motion", mc.j2 ? "two-body + J2" : "two-body"}};
}

nlohmann::json usage_json(const std::vector<assessment::UsageFlag>& flags) {
  nlohmann::json a = nlohmann::json::array();
  for (const assessment::UsageFlag& f : flags) {
    a.push_back({{"check", f.name}, {"value", f.value}, {"threshold", f.threshold},
                 {"violated", f.violated}, {"meaning", f.meaning}});
  }
  return a;
}

void add_choice_json(const assessment::PcChoice& c, nlohmann::json* j) {
  (*j)["method_reason"] = c.why;
  (*j)["usage"] = {{"pc_2d", usage_json(c.usage_2d)}};
  if (!c.nc3d) return;  // 3x3 covariances: no 3D-Nc
  const assessment::Nc3dResult& n = *c.nc3d;
  (*j)["pc_3d_nc"] = n.pc;
  (*j)["usage"]["pc_3d_nc"] = usage_json(c.usage_3d_nc);
  (*j)["nc3d"] = {{"window_s", {n.t_begin_s, n.t_end_s}}, {"t_peak_s", n.t_peak_s},
                  {"converged", n.converged}, {"failure", n.failure},
                  {"rate_evaluations", n.rate_evaluations}, {"pc_small_hbr", n.pc_small_hbr}};
  if (c.spans) {
    (*j)["nc3d"]["segment_s"] = {c.spans->segment_begin_s, c.spans->segment_end_s};
    (*j)["nc3d"]["conjunction_span_s"] = {c.spans->conj_begin_s, c.spans->conj_end_s};
  }
}

// The recommended Pc and the checks behind it, for the text output.
std::string choice_text(const AssessResult& r) {
  char b[300];
  std::string t;
  (void)std::snprintf(b, sizeof b, "  Pc %.6e by %s (%s)\n", r.pc, r.method.c_str(),
                      r.choice ? r.choice->why.c_str() : "encounter plane given: 2D only");
  t += b;
  if (!r.choice) return t;
  auto flags = [&](const char* what, const std::vector<assessment::UsageFlag>& f) {
    for (const assessment::UsageFlag& u : f) {
      (void)std::snprintf(b, sizeof b, "    %s %-10s %.4g (limit %.4g)%s: %s\n", what,
                          u.name.c_str(), u.value, u.threshold, u.violated ? " FAILS" : "",
                          u.meaning.c_str());
      t += b;
    }
  };
  flags("2D   ", r.choice->usage_2d);
  if (r.choice->nc3d) {
    (void)std::snprintf(b, sizeof b, "  Pc 3D-Nc %.6e over [%.1f, %.1f] s about TCA\n",
                        r.choice->nc3d->pc, r.choice->nc3d->t_begin_s, r.choice->nc3d->t_end_s);
    t += b;
    flags("3D-Nc", r.choice->usage_3d_nc);
  }
  return t;
}

nlohmann::json cdm_json(const CdmFigures& c) {
  return {{"message_id", c.message_id},
          {"tca", c.tca_utc},
          {"miss_distance_m", optional_json(c.miss_distance_m)},
          {"relative_speed_mps", optional_json(c.relative_speed_mps)},
          {"collision_probability", optional_json(c.collision_probability)},
          {"collision_probability_method", optional_json(c.collision_probability_method)}};
}

// Object i's covariance repair: for the text output (text true) or as a warning.
std::string repair_line(const StatesAtTca& s, int i, bool text) {
  char b[200];
  if (text) {
    (void)std::snprintf(b, sizeof b,
                        "  object %d covariance repaired (not positive definite, smallest "
                        "eigenvalue %.6e, clipped)\n",
                        i + 1, s.covariance_min_eigenvalue_m2[i]);
  } else {
    (void)std::snprintf(b, sizeof b,
                        "object %d's covariance is not positive definite (smallest eigenvalue "
                        "%.6e): repaired by eigenvalue clipping before the Pc",
                        i + 1, s.covariance_min_eigenvalue_m2[i]);
  }
  return b;
}

}  // namespace

AssessRequest read_assess_request(const config::Scenario& sc) {
  AssessRequest r;
  config::read_params(sc, "assessment.", assessment::assess_params(), &r.config);
  r.conjunction = read_conjunction_scenario(sc);
  sc.check_all_used();
  r.source = "scenario " + sc.source();
  return r;
}

AssessRequest read_assess_request_cdm(const config::Scenario& sc, const std::string& cdm_text,
                                      const std::string& cdm_name, double hbr_m) {
  AssessRequest r;
  config::read_params(sc, "assessment.", assessment::assess_params(), &r.config);
  r.cdm = ccsds::read_cdm_text(cdm_text);
  r.conjunction = conjunction_from_cdm(*r.cdm, hbr_m, config::read_earth(sc));
  sc.check_all_used();
  r.source = "cdm " + cdm_name;
  return r;
}

AssessRequest encounter_plane_request(const assessment::PrincipalEncounter& plane, double hbr_m) {
  AssessRequest r;
  r.source = "encounter plane";
  r.encounter_plane = plane;
  r.plane_hbr_m = hbr_m;
  return r;
}

AssessResult run_assess(const AssessRequest& req) {
  if (req.encounter_plane) return run_plane(req, *req.encounter_plane);
  if (!req.conjunction)
    throw std::invalid_argument("assess: no encounter given (states or an encounter plane)");
  return run_states(req, *req.conjunction);
}

nlohmann::json to_json(const AssessResult& r) {
  nlohmann::json j = {{"source", r.source}, {"hbr_m", r.hbr_m}, {"miss_m", r.miss_m},
                      {"rel_speed_mps", optional_json(r.rel_speed_mps)}, {"pc_2d", r.pc_2d},
                      {"pc_chan", r.pc_chan}, {"pc_max", r.pc_max.pc_max},
                      {"pc_max_scale", r.pc_max.scale}, {"encounter_plane", plane_json(r)}};
  if (r.pc_2d_abs_error) j["pc_2d_abs_error"] = *r.pc_2d_abs_error;
  if (r.states) add_states_json(*r.states, &j);
  if (r.pc_mc) {
    add_monte_carlo_json(*r.pc_mc, &j);
    j["ranks"] = r.mc_ranks;
  }
  j["pc"] = r.pc;
  j["method"] = r.method;
  if (r.choice) add_choice_json(*r.choice, &j);
  if (r.cdm) {
    j["cdm"] = cdm_json(*r.cdm);
    j["notes"] = r.cdm->unit_notes;
  }
  return j;
}

std::string to_text(const AssessResult& r) {
  char b[256];
  (void)std::snprintf(b, sizeof b, ": miss %.3f m, HBR %.3f m\n", r.miss_m, r.hbr_m);
  std::string t = r.source + b;
  if (r.states && r.rel_speed_mps) {  // run_states sets both
    (void)std::snprintf(b, sizeof b,
                        "  at TCA (%+.6f s from the epoch of the given states): relative speed "
                        "%.3f m/s\n",
                        r.states->tca_shift_s, *r.rel_speed_mps);
    t += b;
  }
  if (r.cdm) t += "  CDM " + r.cdm->message_id + ": TCA " + r.cdm->tca_utc + " UTC\n";
  if (std::isnan(r.pc_2d)) {
    t += "  Pc 2D, Chan, max: undefined (zero relative speed: no encounter plane)\n";
  } else {
    (void)std::snprintf(b, sizeof b, "  Pc 2D %.6e  Chan %.6e  max %.6e\n", r.pc_2d, r.pc_chan,
                        r.pc_max.pc_max);
    t += b;
  }
  if (r.pc_mc) {
    (void)std::snprintf(b, sizeof b, "  Pc Monte Carlo %.6e  [%.6e, %.6e]\n", r.pc_mc->pc,
                        r.pc_mc->pc_low, r.pc_mc->pc_high);
    t += b;
  }
  t += choice_text(r);
  if (!r.states) return t;
  if (!r.states->short_term.valid)
    t += "  short-term assumptions fail: " + r.states->short_term.reason + "\n";
  for (int i = 0; i < 2; ++i) {
    if (!r.states->covariance_repaired[i]) continue;
    t += repair_line(*r.states, i, true);
  }
  if (r.cdm)
    for (const std::string& n : r.cdm->unit_notes) t += "  note: " + n + "\n";
  return t;
}

std::vector<std::string> assess_warnings(const AssessResult& r) {
  std::vector<std::string> w;
  if (!r.states) return w;
  for (int i = 0; i < 2; ++i) {
    if (!r.states->covariance_repaired[i]) continue;
    w.push_back(repair_line(*r.states, i, false));
  }
  if (r.cdm)
    for (const std::string& n : r.cdm->unit_notes) w.push_back("note: " + n);
  return w;
}

}  // namespace evade::commands
