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
  r.plane_pc = assessment::plane_pc_values(pe, r.hbr_m, 1e-8);
  // The quadrature's error estimate is reported from states only (as it always was).
  for (assessment::PcValue& v : r.plane_pc) {
    if (v.method == assessment::PcMethod::k2d) v.figures.clear();
  }
  r.miss_m = std::hypot(pe.miss_x_m, pe.miss_y_m);
  r.principal = pe;
  r.pc = assessment::pc_of(r.plane_pc, assessment::PcMethod::k2d);
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
  r.plane_pc = a.plane_pc;
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

// "pc_<name>" and "pc_<name>_<figure>" of one method (pc_methods.hpp).
void add_pc_json(const assessment::PcValue& v, nlohmann::json* j) {
  const std::string key = std::string("pc_") + assessment::pc_method(v.method).name;
  (*j)[key] = v.pc;
  for (const assessment::PcFigure& f : v.figures) (*j)[key + "_" + f.name] = f.value;
}

void add_monte_carlo_json(const assessment::MonteCarloResult& mc, nlohmann::json* j) {
  add_pc_json(assessment::monte_carlo_value(mc), j);
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
  (*j)["usage"] = nlohmann::json::object();
  for (const assessment::PcStep& s : c.steps) {
    const assessment::PcMethodRow& row = assessment::pc_method(s.value.method);
    if (row.check_noun != nullptr) (*j)["usage"][std::string("pc_") + row.name] = usage_json(s.usage);
    add_pc_json(s.value, j);
  }
  if (!c.nc3d) return;  // 3x3 covariances: no 3D-Nc
  const assessment::Nc3dResult& n = *c.nc3d;
  (*j)["nc3d"] = {{"window_s", {n.t_begin_s, n.t_end_s}}, {"t_peak_s", n.t_peak_s},
                  {"converged", n.converged}, {"failure", n.failure},
                  {"rate_evaluations", n.rate_evaluations}, {"pc_small_hbr", n.pc_small_hbr}};
  if (c.spans) {
    (*j)["nc3d"]["segment_s"] = {c.spans->segment_begin_s, c.spans->segment_end_s};
    (*j)["nc3d"]["conjunction_span_s"] = {c.spans->conj_begin_s, c.spans->conj_end_s};
  }
}

// A step's Pc line: "  Pc 3D-Nc 1.0e-02 over [-2400.0, 2400.0] s about TCA".
std::string step_pc_line(const assessment::PcChoice& c, const assessment::PcStep& s,
                         const assessment::PcMethodRow& row) {
  char b[200];
  (void)std::snprintf(b, sizeof b, "  Pc %s %.6e", row.label, s.value.pc);
  std::string t = b;
  if (s.value.method == assessment::PcMethod::k3dNc && c.nc3d) {
    (void)std::snprintf(b, sizeof b, " over [%.1f, %.1f] s about TCA", c.nc3d->t_begin_s,
                        c.nc3d->t_end_s);
    t += b;
  }
  return t + "\n";
}

// The plane methods' Pc line: "  Pc 2D 3.4e-02  Chan 3.4e-02  max 5.0e-02", or the labels and
// "undefined" when there is no encounter plane.
std::string plane_pc_line(const std::vector<assessment::PcValue>& values) {
  std::string labels, line = "  Pc";
  bool undefined = false;
  char b[64];
  for (const assessment::PcValue& v : values) {
    const char* label = assessment::pc_method(v.method).label;
    labels += (labels.empty() ? " " : ", ") + std::string(label);
    (void)std::snprintf(b, sizeof b, "%s%s %.6e", line.size() > 4 ? "  " : " ", label, v.pc);
    line += b;
    undefined = undefined || std::isnan(v.pc);
  }
  if (undefined) return "  Pc" + labels + ": undefined (zero relative speed: no encounter plane)\n";
  return line + "\n";
}

// The recommended Pc and the checks behind it, for the text output.
std::string choice_text(const AssessResult& r) {
  char b[300];
  std::string t;
  (void)std::snprintf(b, sizeof b, "  Pc %.6e by %s (%s)\n", r.pc, r.method.c_str(),
                      r.choice ? r.choice->why.c_str() : "encounter plane given: 2D only");
  t += b;
  if (!r.choice) return t;
  // Each step with checks: its Pc (unless a plane method, on the Pc line already), then
  // its checks.
  for (const assessment::PcStep& s : r.choice->steps) {
    const assessment::PcMethodRow& row = assessment::pc_method(s.value.method);
    if (row.check_noun == nullptr) continue;
    if (row.from_plane == nullptr) t += step_pc_line(*r.choice, s, row);
    for (const assessment::UsageFlag& u : s.usage) {
      (void)std::snprintf(b, sizeof b, "    %-5s %-10s %.4g (limit %.4g)%s: %s\n", row.label,
                          u.name.c_str(), u.value, u.threshold, u.violated ? " FAILS" : "",
                          u.meaning.c_str());
      t += b;
    }
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
                      {"rel_speed_mps", optional_json(r.rel_speed_mps)},
                      {"encounter_plane", plane_json(r)}};
  for (const assessment::PcValue& v : r.plane_pc) add_pc_json(v, &j);
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
  t += plane_pc_line(r.plane_pc);
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
