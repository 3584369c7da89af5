// The burn-plan file (plan_file.hpp): JSON with nlohmann::json, validated field by field.
#include "evade/commands/plan_file.hpp"

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/config/json_values.hpp"

namespace evade::commands {
namespace {

using nlohmann::json;

constexpr double kMaxAbsTimeS = 1e9;  // as the executor's NOT_FINITE rule (PLAN-VAL-1)

struct Source {
  PlanSource code;
  const char* name;
};
constexpr Source kSources[] = {{PlanSource::kUnknown, "unknown"},
                               {PlanSource::kThreatArea, "threat-area"},
                               {PlanSource::kFormation, "formation"},
                               {PlanSource::kObservability, "observability"},
                               {PlanSource::kCollisionAvoidance, "collision-avoidance"}};

[[noreturn]] void fail(const std::string& where, const std::string& field,
                       const std::string& what) {
  throw std::invalid_argument(where + field + " " + what);
}

void check_keys(const json& obj, const std::set<std::string>& allowed, const std::string& where,
                const std::string& prefix) {
  for (auto it = obj.begin(); it != obj.end(); ++it) {
    if (allowed.count(it.key()) == 0)
      fail(where, prefix + it.key(), "is not a known key of the plan file");
  }
}

double finite_number(const json& v, const std::string& where, const std::string& field) {
  if (!v.is_number()) fail(where, field, "= " + v.dump() + ": expected a number");
  const double x = v.get<double>();
  if (!std::isfinite(x)) fail(where, field, "= " + v.dump() + ": must be finite");
  return x;
}

Vec3 vec3(const json& v, const std::string& where, const std::string& field) {
  if (!v.is_array() || v.size() != 3)
    fail(where, field, "= " + v.dump() + ": expected [x, y, z] (3 numbers, m/s)");
  Vec3 out;
  for (int i = 0; i < 3; ++i)
    out(i) = finite_number(v[static_cast<std::size_t>(i)], where,
                           field + "[" + std::to_string(i) + "]");
  return out;
}

const json& required(const json& obj, const char* key, const std::string& where,
                     const std::string& prefix) {
  const auto it = obj.find(key);
  if (it == obj.end()) fail(where, prefix + key, "is missing");
  return *it;
}

ImpulsiveBurn read_impulse(const json& j, const std::string& where, const std::string& prefix) {
  if (!j.is_object()) fail(where, prefix.substr(0, prefix.size() - 1), "must be an object");
  check_keys(j, {"t_s", "dv_rsw_mps", "dv_eci_mps"}, where, prefix);
  ImpulsiveBurn b;
  b.t_s = finite_number(required(j, "t_s", where, prefix), where, prefix + "t_s");
  if (std::abs(b.t_s) > kMaxAbsTimeS)
    fail(where, prefix + "t_s", "= " + std::to_string(b.t_s) + ": |t| must be <= 1e9 s");
  b.dv_rsw_mps = vec3(required(j, "dv_rsw_mps", where, prefix), where, prefix + "dv_rsw_mps");
  const auto eci = j.find("dv_eci_mps");
  b.dv_eci_valid = eci != j.end() && !eci->is_null();
  if (b.dv_eci_valid) b.dv_eci_mps = vec3(*eci, where, prefix + "dv_eci_mps");
  return b;
}

int read_source(const json& j, const std::string& where) {
  if (j.is_string())
    for (const Source& s : kSources)
      if (j.get<std::string>() == s.name) return static_cast<int>(s.code);
  fail(where, "source", "= " + j.dump() +
                            ": expected \"threat-area\", \"formation\", \"observability\", "
                            "\"collision-avoidance\" or \"unknown\"");
}

guidance::PlanFrame read_frame(const json& j, const std::string& where) {
  if (j == "rsw") return guidance::PlanFrame::kRsw;
  if (j == "eci") return guidance::PlanFrame::kEci;
  fail(where, "frame", "= " + j.dump() + ": expected \"rsw\" or \"eci\"");
}

void read_impulses(const json& arr, const std::string& where, PlanFile* f) {
  if (!arr.is_array() || arr.empty() || arr.size() > BurnPlan::kMaxImpulses)
    fail(where, "impulses", "must be a list of 1.." + std::to_string(BurnPlan::kMaxImpulses) +
                                " impulses (has " +
                                std::to_string(arr.is_array() ? arr.size() : 0) + ")");
  f->plan.n_impulses = static_cast<int>(arr.size());
  for (std::size_t i = 0; i < arr.size(); ++i) {
    const std::string prefix = "impulses[" + std::to_string(i) + "].";
    f->plan.impulses[i] = read_impulse(arr[i], where, prefix);
    if (i > 0 && !(f->plan.impulses[i].t_s > f->plan.impulses[i - 1].t_s))
      fail(where, prefix + "t_s", "= " + std::to_string(f->plan.impulses[i].t_s) +
                                      ": impulse times must be strictly increasing (previous " +
                                      std::to_string(f->plan.impulses[i - 1].t_s) + ")");
    if (f->frame == guidance::PlanFrame::kEci && !f->plan.impulses[i].dv_eci_valid)
      fail(where, prefix + "dv_eci_mps", "is missing: frame \"eci\" needs every impulse's ECI Δv");
  }
}

}  // namespace

const char* plan_source_name(int code) {
  for (const Source& s : kSources)
    if (static_cast<int>(s.code) == code) return s.name;
  throw std::invalid_argument("plan file: BurnPlan.source = " + std::to_string(code) +
                              " is not a known planner");
}

PlanFile parse_plan_file(const std::string& text, const std::string& source) {
  const std::string where = "plan file '" + source + "': ";
  json j;
  try {
    j = json::parse(text);
  } catch (const json::exception& e) {  // parse errors, and numbers overflowing a double
    throw std::invalid_argument(where + "not valid JSON (" + e.what() + ")");
  }
  if (!j.is_object()) throw std::invalid_argument(where + "must be a JSON object");
  check_keys(j, {"format", "plan_id", "source", "frame", "impulses"}, where, "");
  const json& format = required(j, "format", where, "");
  if (format != kPlanFileFormat)
    fail(where, "format", "= " + format.dump() + ": expected \"" + kPlanFileFormat + "\"");
  PlanFile f;
  const json& id = required(j, "plan_id", where, "");
  if (!id.is_number_integer() || id.get<long long>() < 0)
    fail(where, "plan_id", "= " + id.dump() + ": expected an integer >= 0");
  f.plan.plan_id = id.get<long long>();
  f.plan.source = read_source(required(j, "source", where, ""), where);
  f.frame = read_frame(required(j, "frame", where, ""), where);
  read_impulses(required(j, "impulses", where, ""), where, &f);
  return f;
}

std::string plan_file_json(const PlanFile& f) {
  json j;
  j["format"] = kPlanFileFormat;
  j["plan_id"] = f.plan.plan_id;
  j["source"] = plan_source_name(f.plan.source);
  j["frame"] = f.frame == guidance::PlanFrame::kEci ? "eci" : "rsw";
  j["impulses"] = config::impulses_json(f.plan);
  std::string text = j.dump(2) + "\n";
  (void)parse_plan_file(text, "(being written)");  // the reader's rules, field named
  return text;
}

PlanFile read_plan_file(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::invalid_argument("plan file '" + path + "': cannot be opened");
  std::ostringstream ss;
  ss << in.rdbuf();
  return parse_plan_file(ss.str(), path);
}

void write_plan_file(const std::string& path, const PlanFile& f) {
  const std::string text = plan_file_json(f);
  std::ofstream out(path);
  if (!out || !(out << text) || !out.flush())
    throw std::invalid_argument("plan file '" + path + "': cannot be written");
}

}  // namespace evade::commands
