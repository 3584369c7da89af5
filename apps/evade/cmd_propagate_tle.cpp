// `evade propagate --tle FILE | --omm FILE --span-s S --step-s D --frame teme|eci [--json]`:
// reads the file (the only I/O), asks evade::sgp4 for the catalog and the states, prints.
// Times: t_s counts from the latest element epoch in the file (start_utc), so every object
// is propagated over the same instants. eci is J2000 (teme_to_j2000.hpp).
#include "cmd_propagate_tle.hpp"

#include <algorithm>
#include <cstdio>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "cli.hpp"
#include "evade/core/epoch.hpp"
#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/teme_to_j2000.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::cli {
namespace {

constexpr double kMaxSpanS = 366.0 * 86400.0;  // one year of SGP4 is already far past its use
constexpr double kMaxStepsPerObject = 100000.0;

void check_options(const CatalogPropagateOptions& o) {
  if (!(o.span_s >= 0.0 && o.span_s <= kMaxSpanS))
    throw std::invalid_argument("--span-s = " + std::to_string(o.span_s) +
                                " is invalid: expected a number in [0, 31622400] s");
  if (!(o.step_s > 0.0) || o.span_s / o.step_s > kMaxStepsPerObject)
    throw std::invalid_argument("--step-s = " + std::to_string(o.step_s) +
                                " is invalid: expected a number > 0 with span/step <= 100000");
  if (o.frame != "teme" && o.frame != "eci")
    throw std::invalid_argument("--frame = '" + o.frame + "' is invalid: expected teme or eci");
}

nlohmann::json vec(const Eigen::Vector3d& v) { return {v.x(), v.y(), v.z()}; }

nlohmann::json propagate_object(const sgp4::MeanElements& m, double start_j2000_s,
                                const CatalogPropagateOptions& o) {
  nlohmann::json obj;
  obj["id"] = m.norad_id;
  obj["name"] = m.name;
  obj["epoch_utc"] = format_calendar_utc(calendar_from_seconds_since_j2000(sgp4::epoch_seconds_since_j2000(m)));
  nlohmann::json states = nlohmann::json::array();
  const sgp4::Sgp4Propagator prop(m, sgp4::OperationMode::kImproved);
  const double offset_s = start_j2000_s - sgp4::epoch_seconds_since_j2000(m);
  const long n = static_cast<long>(o.span_s / o.step_s + 1e-9);
  for (long k = 0; k <= n; ++k) {
    const double t_s = std::min(static_cast<double>(k) * o.step_s, o.span_s);
    const sgp4::Sgp4State s = prop.propagate_s(offset_s + t_s);
    if (s.error != sgp4::Sgp4Error::kNone) {
      obj["sgp4_error"] = {{"t_s", t_s}, {"code", static_cast<int>(s.error)}, {"text", sgp4::sgp4_error_text(s.error)}};
      break;
    }
    Eigen::Vector3d r = s.r_teme_m, v = s.v_teme_mps;
    if (o.frame == "eci") sgp4::teme_to_j2000(start_j2000_s + t_s, s.r_teme_m, s.v_teme_mps, r, v);
    states.push_back({{"t_s", t_s}, {"r_m", vec(r)}, {"v_mps", vec(v)}});
  }
  obj["states"] = std::move(states);
  return obj;
}

void print_text(const nlohmann::json& j) {
  std::printf("evade propagate: %zu objects (%d bad entries), frame %s, from %s\n", j["objects"].size(),
              j["bad_entries"].get<int>(), j["frame"].get<std::string>().c_str(),
              j["start_utc"].get<std::string>().c_str());
  for (const auto& obj : j["objects"]) {
    const auto& st = obj["states"];
    std::printf("  %6ld %-24s %zu states", obj["id"].get<long>(), obj["name"].get<std::string>().c_str(), st.size());
    if (!st.empty()) {
      const auto& last = st.back();
      std::printf(", at t = %.0f s r_m = [%.1f, %.1f, %.1f]", last["t_s"].get<double>(), last["r_m"][0].get<double>(),
                  last["r_m"][1].get<double>(), last["r_m"][2].get<double>());
    }
    if (obj.contains("sgp4_error")) std::printf(" (stopped: %s)", obj["sgp4_error"]["text"].get<std::string>().c_str());
    std::printf("\n");
  }
}

}  // namespace

int run_propagate_catalog(const CatalogPropagateOptions& o) {
  check_options(o);
  const sgp4::Catalog cat = read_catalog_file(o.tle_path, o.omm_path);
  for (const auto& is : cat.issues) (void)std::fprintf(stderr, "evade propagate: bad entry: %s\n", is.message().c_str());
  if (cat.objects.empty())
    throw std::invalid_argument("no valid element set in the file (" + std::to_string(cat.bad_entries) + " bad entries)");
  double start_s = sgp4::epoch_seconds_since_j2000(cat.objects[0]);
  for (const auto& m : cat.objects) start_s = std::max(start_s, sgp4::epoch_seconds_since_j2000(m));
  nlohmann::json j;
  j["start_utc"] = format_calendar_utc(calendar_from_seconds_since_j2000(start_s));
  j["frame"] = o.frame == "eci" ? "J2000" : "TEME";
  j["bad_entries"] = cat.bad_entries;
  j["issues"] = nlohmann::json::array();
  for (const auto& is : cat.issues) j["issues"].push_back(is.message());
  j["objects"] = nlohmann::json::array();
  for (const auto& m : cat.objects) j["objects"].push_back(propagate_object(m, start_s, o));
  if (o.json) print_json(j);
  else print_text(j);
  return 0;
}

}  // namespace evade::cli
