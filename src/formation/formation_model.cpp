// Formation model and constraint quantities of paper 003 sec. 1 (see formation_model.hpp).
#include "evade/formation/formation_model.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "evade/core/earth_params.hpp"
#include "evade/core/elements.hpp"

namespace evade::formation {
namespace {

[[noreturn]] void fail(const std::string& field, double v, const std::string& range) {
  throw std::invalid_argument("formation: " + field + " = " + std::to_string(v) +
                              " outside " + range);
}

void check(const std::string& field, double v, double lo, double hi, const std::string& range) {
  if (!std::isfinite(v) || v < lo || v > hi) fail(field, v, range);
}

}  // namespace

const char* role_name(Role r) {
  switch (r) {
    case Role::kChief: return "chief";
    case Role::kDeputy1: return "deputy1";
    case Role::kDeputy2: return "deputy2";
  }
  return "?";
}

const char* constraint_kind_name(ConstraintKind k) {
  switch (k) {
    case ConstraintKind::kInterGroupRaan: return "inter_group_raan";
    case ConstraintKind::kInterGroupPhase: return "inter_group_phase";
    case ConstraintKind::kOutOfPlane: return "out_of_plane";
    case ConstraintKind::kInPlane: return "in_plane";
  }
  return "?";
}

std::string FormationSpec::sat_name(const SatelliteId& id) const {
  return groups.at(id.group).name + "." + role_name(id.role);
}

void FormationSpec::validate() const {
  check("side_length_m", side_length_m, 1.0, 1e7, "[1, 1e7] m");
  check("box_delta_m", box_delta_m, 1e-3, side_length_m / 8.0,
        "[1e-3 m, L/8] (the inward in-plane edge L/2 - Δ must stay positive with room)");
  check("raan_tolerance_rad", raan_tolerance_rad, 1e-12, kPi / 2, "(0, pi/2] rad");
  check("phase_tolerance_rad", phase_tolerance_rad, 1e-12, kPi / 2, "(0, pi/2] rad");
  check("horizon_days", horizon_days, 1e-6, 60.0, "(0, 60] day");
  const std::string bad_earth = validate_params(earth_params(), earth, "earth.");
  if (!bad_earth.empty()) throw std::invalid_argument("formation: " + bad_earth);
  if (groups.size() < 2) fail("groups.size", static_cast<double>(groups.size()), "[2, inf)");
  if (reference_group >= groups.size()) {
    fail("reference_group", static_cast<double>(reference_group),
         "[0, " + std::to_string(groups.size() - 1) + "]");
  }
  for (std::size_t g = 0; g < groups.size(); ++g) {
    const Group& gr = groups[g];
    const std::string gp = "groups." + std::to_string(g) + " (" + gr.name + ").";
    check(gp + "nominal_raan_offset_rad", gr.nominal_raan_offset_rad, -kTwoPi, kTwoPi,
          "[-2pi, 2pi] rad");
    check(gp + "nominal_phase_offset_rad", gr.nominal_phase_offset_rad, -kTwoPi, kTwoPi,
          "[-2pi, 2pi] rad");
    for (std::size_t r = 0; r < 3; ++r) {
      const MeanElements& m = gr.sats[r];
      const std::string sp = gp + role_name(static_cast<Role>(r)) + ".";
      check(sp + "a_m", m.a_m, earth.re_m + 1e5, 5e7, "[re_m + 100 km, 5e7] m");
      check(sp + "e", m.e, 0.0, 0.01, "[0, 0.01] (near-circular model)");
      check(sp + "i_rad", m.i_rad, 1e-3, kPi - 1e-3, "[1e-3, pi - 1e-3] rad");
      check(sp + "raan_rad", m.raan_rad, -kTwoPi, kTwoPi, "[-2pi, 2pi] rad");
      check(sp + "arg_lat_rad", m.arg_lat_rad, -kTwoPi, kTwoPi, "[-2pi, 2pi] rad");
    }
  }
}

namespace {

// The inter-group RAAN and phase rows of group g against the reference group.
void add_inter_group(const FormationSpec& spec, std::size_t g, std::vector<ConstraintDef>& out) {
  const std::size_t ref = spec.reference_group;
  const Group& gr = spec.groups[g];
  const std::string tag = "(" + gr.name + "-" + spec.groups[ref].name + ")";
  ConstraintDef c;
  c.first = {g, Role::kChief};
  c.second = {ref, Role::kChief};
  c.kind = ConstraintKind::kInterGroupRaan;
  c.name = std::string("inter_group_raan") + tag;
  c.nominal = gr.nominal_raan_offset_rad;
  c.lower = -spec.raan_tolerance_rad;
  c.upper = spec.raan_tolerance_rad;
  out.push_back(c);
  c.kind = ConstraintKind::kInterGroupPhase;
  c.name = std::string("inter_group_phase") + tag;
  c.nominal = gr.nominal_phase_offset_rad;
  c.lower = -spec.phase_tolerance_rad;
  c.upper = spec.phase_tolerance_rad;
  out.push_back(c);
}

// One box row (out-of-plane or in-plane) per deputy of group g: band [lower, upper] about
// the nominal value.
void add_box_rows(const FormationSpec& spec, std::size_t g, ConstraintKind kind,
                  const std::string& prefix, double nominal, double lower, double upper,
                  std::vector<ConstraintDef>& out) {
  const std::string gname = "(" + spec.groups[g].name + ")";
  for (Role dep : {Role::kDeputy1, Role::kDeputy2}) {
    ConstraintDef c;
    c.first = {g, dep};
    c.second = {g, Role::kChief};
    c.kind = kind;
    c.name = prefix;
    c.name.append(role_name(dep)).append(gname);
    c.nominal = nominal;
    c.lower = lower;
    c.upper = upper;
    out.push_back(c);
  }
}

}  // namespace

std::vector<ConstraintDef> constraints_for(const FormationSpec& spec,
                                           const SatelliteId& threatened) {
  spec.validate();
  if (threatened.group >= spec.groups.size()) {
    fail("threatened.group", static_cast<double>(threatened.group),
         "[0, " + std::to_string(spec.groups.size() - 1) + "]");
  }
  std::vector<ConstraintDef> out;
  const std::size_t ref = spec.reference_group;
  if (threatened.group != ref) {
    add_inter_group(spec, threatened.group, out);
  } else {
    for (std::size_t g = 0; g < spec.groups.size(); ++g) {
      if (g != ref) add_inter_group(spec, g, out);
    }
  }
  const double d = spec.box_delta_m;
  const double l = spec.side_length_m;
  add_box_rows(spec, threatened.group, ConstraintKind::kOutOfPlane, "out_of_plane_",
               l * std::sqrt(3.0) / 2.0, -6.0 * d, 3.0 * d, out);
  add_box_rows(spec, threatened.group, ConstraintKind::kInPlane, "in_plane_", l / 2.0, -d,
               4.0 * d, out);
  return out;
}

double raw_quantity(ConstraintKind kind, const MeanElements& f, const MeanElements& s) {
  const double d_raan = wrap_pi(f.raan_rad - s.raan_rad);
  switch (kind) {
    case ConstraintKind::kInterGroupRaan: return d_raan;
    case ConstraintKind::kInterGroupPhase: return wrap_pi(f.arg_lat_rad - s.arg_lat_rad);
    case ConstraintKind::kOutOfPlane: {
      const double di = f.i_rad - s.i_rad;
      const double dq = d_raan * std::sin(s.i_rad);
      // The deputy's cross-track distance from the chief's plane: its own radius times the
      // angle between the planes (a change of the chief's a does not move the deputy).
      return f.a_m * std::sqrt(di * di + dq * dq);
    }
    case ConstraintKind::kInPlane:
      return s.a_m * std::abs(wrap_pi(f.arg_lat_rad - s.arg_lat_rad + d_raan * std::cos(s.i_rad)));
  }
  return 0.0;
}

double deviation(const ConstraintDef& c, const MeanElements& f, const MeanElements& s) {
  const double raw = raw_quantity(c.kind, f, s);
  if (c.kind == ConstraintKind::kInterGroupRaan || c.kind == ConstraintKind::kInterGroupPhase) {
    return wrap_pi(raw - c.nominal);
  }
  return raw - c.nominal;
}

double margin(const ConstraintDef& c, double dev) { return std::min(dev - c.lower, c.upper - dev); }

}  // namespace evade::formation
