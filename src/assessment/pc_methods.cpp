// The collision-probability methods, one row each (see pc_methods.hpp).
#include "evade/assessment/pc_methods.hpp"

#include <limits>
#include <stdexcept>

#include "evade/assessment/pc_method_choice.hpp"

namespace evade::assessment {
namespace {

PcValue plane_2d(const PrincipalEncounter& pe, double hbr_m, double rel_tol) {
  const Pc2dResult r = pc_2d(pe, hbr_m, rel_tol);
  return {PcMethod::k2d, r.pc, {{"abs_error", r.abs_error}}};
}

PcValue plane_chan(const PrincipalEncounter& pe, double hbr_m, double /*rel_tol*/) {
  return {PcMethod::kChan, pc_chan(pe, hbr_m), {}};
}

PcValue plane_max(const PrincipalEncounter& pe, double hbr_m, double /*rel_tol*/) {
  const PcMaxResult r = pc_max_alfano(pe, hbr_m);
  return {PcMethod::kMax, r.pc_max, {{"scale", r.scale}}};
}

}  // namespace

// The table: plane methods first, then the escalation's order (2D, 3D-Nc, Monte Carlo). Built on
// first use (a function-local static), so that an allocation failure is thrown to a caller that
// can catch it rather than before main.
const std::vector<PcMethodRow>& pc_methods() {
  static const std::vector<PcMethodRow> rows = {
    {PcMethod::k2d, "2d", "2D", "FOSTER-1992", {"abs_error", nullptr}, &plane_2d,
     &escalate_2d, "usage check", false, false},
    {PcMethod::kChan, "chan", "Chan", nullptr, {nullptr, nullptr}, &plane_chan, nullptr,
     nullptr, false, false},
    {PcMethod::kMax, "max", "max", nullptr, {"scale", nullptr}, &plane_max, nullptr, nullptr,
     false, false},
    {PcMethod::k3dNc, "3d_nc", "3D-Nc", "HALL-2021", {nullptr, nullptr}, nullptr,
     &escalate_3d_nc, "check", true, true},
    {PcMethod::kMc, "mc", "Monte Carlo", "ALFANO-2009", {"low", "high"}, nullptr, &escalate_mc,
     nullptr, false, false},
  };
  return rows;
}

const PcMethodRow& pc_method(PcMethod m) {
  for (const PcMethodRow& r : pc_methods()) {
    if (r.id == m) return r;
  }
  throw std::logic_error("pc_method: a PcMethod without its row");
}

const PcMethodRow* pc_method_named(const std::string& name) {
  for (const PcMethodRow& r : pc_methods()) {
    if (name == r.name) return &r;
  }
  return nullptr;
}

std::vector<PcValue> plane_pc_values(const PrincipalEncounter& pe, double hbr_m, double rel_tol) {
  std::vector<PcValue> v;
  for (const PcMethodRow& r : pc_methods()) {
    if (r.from_plane != nullptr) v.push_back(r.from_plane(pe, hbr_m, rel_tol));
  }
  return v;
}

std::vector<PcValue> undefined_plane_pc_values() {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  std::vector<PcValue> v;
  for (const PcMethodRow& r : pc_methods()) {
    if (r.from_plane == nullptr) continue;
    PcValue u{r.id, nan, {}};
    for (const char* f : r.figures) {
      if (f != nullptr) u.figures.push_back({f, nan});
    }
    v.push_back(u);
  }
  return v;
}

double pc_of(const std::vector<PcValue>& values, PcMethod m) {
  for (const PcValue& v : values) {
    if (v.method == m) return v.pc;
  }
  return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace evade::assessment
