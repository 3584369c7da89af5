// `evade assess`: collision probability of one conjunction (issue 12). The encounter comes
// from a scenario's `conjunction:` block (--scenario), a CCSDS CDM (--cdm, KVN or XML) or the
// encounter plane directly (--encounter-plane MISS_X_M,MISS_Y_M,SIGMA_X_M,SIGMA_Y_M,HBR_M).
// Parses, calls evade::assessment and prints; --json prints miss_m, rel_speed_mps, pc_2d,
// pc_chan, pc_max (and pc_mc, pc_mc_low, pc_mc_high with --mc N --seed S), the encounter
// plane used, how the states were brought to TCA and the short-term validity verdict; with
// --cdm also the message's own TCA, MISS_DISTANCE, RELATIVE_SPEED and COLLISION_PROBABILITY.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli.hpp"
#include "number_list.hpp"
#include "evade/assessment/assess.hpp"
#include "evade/assessment/conjunction_input.hpp"
#include "evade/config/read_params.hpp"

namespace evade::cli {
namespace {

using namespace evade::assessment;

struct Options {
  std::string scenario, cdm, plane;
  std::vector<std::string> sets;
  bool json = false;
  double hbr_m = 0.0;
  long mc = 0;
  std::uint64_t seed = 1;
};

nlohmann::json plane_json(const EncounterPlane* ep, const PrincipalEncounter& pe) {
  nlohmann::json j;
  if (ep) {
    j["miss_x_m"] = ep->miss_m(0);
    j["miss_y_m"] = ep->miss_m(1);
    j["cov_m2"] = {{ep->cov_m2(0, 0), ep->cov_m2(0, 1)}, {ep->cov_m2(1, 0), ep->cov_m2(1, 1)}};
  }
  j["principal"] = {{"miss_x_m", pe.miss_x_m}, {"miss_y_m", pe.miss_y_m},
                    {"sigma_x_m", pe.sigma_x_m}, {"sigma_y_m", pe.sigma_y_m}};
  return j;
}

nlohmann::json run_plane(const Options& o) {
  const std::vector<double> v = parse_number_list(o.plane, ',');
  if (v.size() != 5) {
    throw std::invalid_argument("--encounter-plane: expected MISS_X_M,MISS_Y_M,SIGMA_X_M,"
                                "SIGMA_Y_M,HBR_M, found '" + o.plane + "'");
  }
  if (o.mc > 0) throw std::invalid_argument("--mc needs states (--scenario or --cdm)");
  const PrincipalEncounter pe{v[0], v[1], v[2], v[3]};
  const PcMaxResult mx = pc_max_alfano(pe, v[4]);
  return {{"source", "encounter plane"}, {"hbr_m", v[4]},
          {"miss_m", std::hypot(v[0], v[1])}, {"rel_speed_mps", nullptr},
          {"pc_2d", pc_2d(pe, v[4]).pc}, {"pc_chan", pc_chan(pe, v[4])},
          {"pc_max", mx.pc_max}, {"pc_max_scale", mx.scale},
          {"encounter_plane", plane_json(nullptr, pe)}};
}

nlohmann::json assessment_json(const Assessment& a, double hbr_m) {
  nlohmann::json j = {{"hbr_m", hbr_m}, {"miss_m", a.plane.miss_3d_m},
                      {"rel_speed_mps", a.plane.rel_speed_mps}, {"pc_2d", a.pc_2d.pc},
                      {"pc_2d_abs_error", a.pc_2d.abs_error}, {"pc_chan", a.pc_chan},
                      {"pc_max", a.pc_max.pc_max}, {"pc_max_scale", a.pc_max.scale},
                      {"encounter_plane", plane_json(&a.plane, a.principal)}};
  j["tca"] = {{"shift_s", a.tca_shift_s}, {"method", a.tca_method},
              {"covariance_propagation", a.covariance_propagation}};
  j["covariance_repaired"] = {a.npd[0], a.npd[1]};
  j["covariance_min_eigenvalue_m2"] = {a.min_eigenvalue[0], a.min_eigenvalue[1]};
  j["short_term"] = {{"valid", a.short_term.valid},
                     {"encounter_time_s", a.short_term.encounter_time_s},
                     {"period_s", a.short_term.period_s},
                     {"reason", a.short_term.reason}};
  if (a.mc) {
    j["pc_mc"] = a.mc->pc;
    j["pc_mc_low"] = a.mc->pc_low;
    j["pc_mc_high"] = a.mc->pc_high;
    j["mc"] = {{"samples", a.mc->samples}, {"hits", a.mc->hits}, {"window_s", a.mc->window_s},
               {"interval", "Wilson 95 %"}};
  }
  return j;
}

// The message's own relative values, beside what is recomputed from its states.
nlohmann::json cdm_json(const Cdm& c) {
  auto num = [&](const char* k) {
    const std::string v = cdm_value(c.relative, k);
    return v.empty() ? nlohmann::json(nullptr) : nlohmann::json(std::stod(v));
  };
  const std::string method = cdm_value(c.relative, "COLLISION_PROBABILITY_METHOD");
  return {{"message_id", cdm_value(c.header, "MESSAGE_ID")},
          {"tca", cdm_value(c.relative, "TCA")},
          {"miss_distance_m", num("MISS_DISTANCE")},
          {"relative_speed_mps", num("RELATIVE_SPEED")},
          {"collision_probability", num("COLLISION_PROBABILITY")},
          {"collision_probability_method", method.empty() ? nlohmann::json(nullptr) : nlohmann::json(method)}};
}

// Every repair and every reading note on stderr as well as in the JSON and the text output:
// a result computed from a repaired covariance must never look like one from the input.
void report_repairs(const nlohmann::json& j) {
  for (int i = 0; i < 2; ++i) {
    if (!j["covariance_repaired"][i].get<bool>()) continue;
    (void)std::fprintf(stderr,
                       "evade assess: object %d's covariance is not positive definite (smallest "
                       "eigenvalue %.6e): repaired by eigenvalue clipping before the Pc\n",
                       i + 1, j["covariance_min_eigenvalue_m2"][i].get<double>());
  }
  if (j.contains("notes")) {
    for (const auto& n : j["notes"]) {
      (void)std::fprintf(stderr, "evade assess: note: %s\n", n.get<std::string>().c_str());
    }
  }
}

nlohmann::json run_states(const Options& o) {
  config::Scenario sc = o.scenario.empty() ? config::Scenario::empty("--cdm")
                                           : config::Scenario::load(o.scenario);
  for (const auto& a : o.sets) sc.apply_override(a);
  AssessConfig cfg;
  config::read_params(sc, "assessment.", assess_params(), &cfg);
  std::optional<Cdm> cdm;
  if (o.scenario.empty()) cdm = read_cdm_text(read_text_file(o.cdm, "--cdm"));
  ConjunctionInput in = cdm ? conjunction_from_cdm(*cdm, o.hbr_m, config::read_earth(sc))
                            : read_conjunction_scenario(sc);
  sc.check_all_used();
  std::optional<MonteCarloOptions> mc;
  if (o.mc > 0) mc = MonteCarloOptions{o.mc, o.seed, 0.0, 1.96};
  nlohmann::json j = assessment_json(assess(in, cfg, mc), in.hbr_m);
  j["source"] = o.scenario.empty() ? "cdm " + o.cdm : "scenario " + sc.source();
  if (cdm) {
    j["cdm"] = cdm_json(*cdm);
    j["notes"] = cdm_unit_notes(*cdm);
  }
  report_repairs(j);
  return j;
}

void print_text(const nlohmann::json& j) {
  std::printf("%s: miss %.3f m, HBR %.3f m\n", j["source"].get<std::string>().c_str(),
              j["miss_m"].get<double>(), j["hbr_m"].get<double>());
  std::printf("  Pc 2D %.6e  Chan %.6e  max %.6e\n", j["pc_2d"].get<double>(),
              j["pc_chan"].get<double>(), j["pc_max"].get<double>());
  if (j.contains("pc_mc"))
    std::printf("  Pc Monte Carlo %.6e  [%.6e, %.6e]\n", j["pc_mc"].get<double>(),
                j["pc_mc_low"].get<double>(), j["pc_mc_high"].get<double>());
  if (j.contains("short_term") && !j["short_term"]["valid"].get<bool>())
    std::printf("  short-term assumptions fail: %s\n",
                j["short_term"]["reason"].get<std::string>().c_str());
  if (j.contains("covariance_repaired")) {
    for (int i = 0; i < 2; ++i) {
      if (j["covariance_repaired"][i].get<bool>()) {
        std::printf("  object %d covariance repaired (not positive definite, smallest eigenvalue "
                    "%.6e, clipped)\n",
                    i + 1, j["covariance_min_eigenvalue_m2"][i].get<double>());
      }
    }
  }
  if (j.contains("notes")) {
    for (const auto& n : j["notes"]) std::printf("  note: %s\n", n.get<std::string>().c_str());
  }
}

int run(const Options& o) {
  const int sources = !o.scenario.empty() + !o.cdm.empty() + !o.plane.empty();
  if (sources != 1)
    throw std::invalid_argument("give exactly one of --scenario, --cdm, --encounter-plane");
  const nlohmann::json j = o.plane.empty() ? run_states(o) : run_plane(o);
  if (o.json) print_json(j); else print_text(j);
  return 0;
}

Runner setup(CLI::App& app) {
  auto o = std::make_shared<Options>();
  app.add_option("--scenario", o->scenario, "scenario with a conjunction: block");
  app.add_option("--cdm", o->cdm, "a CCSDS CDM file (KVN or XML)");
  app.add_option("--encounter-plane", o->plane, "MISS_X_M,MISS_Y_M,SIGMA_X_M,SIGMA_Y_M,HBR_M [m]");
  app.add_option("--set", o->sets, "override a scenario key (repeatable)");
  app.add_option("--hbr-m", o->hbr_m, "hard-body radius for --cdm [m]")->check(CLI::PositiveNumber);
  app.add_option("--mc", o->mc, "Monte Carlo samples [-]")->check(CLI::Range(1L, 100000000L));
  app.add_option("--seed", o->seed, "Monte Carlo seed [-]")->capture_default_str();
  app.add_flag("--json", o->json, "print a machine-readable JSON result on stdout");
  return [o]() { return run(*o); };
}

const bool kRegistered = register_command(
    {{"assess"}, "Collision probability of one conjunction (2D, Chan, max, Monte Carlo)", &setup});

}  // namespace
}  // namespace evade::cli
