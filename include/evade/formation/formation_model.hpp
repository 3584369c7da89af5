// Formation-constellation model of paper 003 (Duan et al.), section 1: N groups of a chief
// and two deputies arranged walker-like around a reference group; the constraint
// quantities of Table 1 as functions of the (mean, near-circular) elements.
//
// Geometry (paper Fig. 1 and Fig. 4). The deputies share a plane whose RAAN differs from
// the chief's by a small δΩ; deputy 1 leads the chief and deputy 2 trails it. For two
// circular orbits of equal a and i with δΩ = Ω_d - Ω_c, δu = u_d - u_c (the deputy relative
// to the chief, first order in the differences, chief RSW frame):
//   along-track  s = a (δu + δΩ cos i)          (constant)
//   cross-track  w = a (δi sin u - δΩ sin i cos u),  amplitude h = a_d sqrt(δi² + (δΩ sin i)²)
//   (a_d: the deputy's semi-major axis — its distance from the chief's plane)
// so at the equator the three satellites form a triangle of height h, and at the highest
// latitude they are collinear with the chief–deputy distance |s| (the paper's "minimum
// inter-satellite distance"). Nominally |s| = L/2 and h = L·sqrt(3)/2 (equilateral
// triangle of side L at the equator).
//
// Constraint quantities (deviation from nominal; each must stay within its bounds):
//   inter-group RAAN   wrap(Ω_c,g − Ω_c,ref) − ΔΩ_nom(g)        ∈ [−Ω_max, +Ω_max]     [rad]
//   inter-group phase  wrap(u_c,g − u_c,ref) − Δφ_nom(g)        ∈ [−Δφ_max, +Δφ_max]   [rad]
//   out-of-plane (k)   h(deputy k, chief) − L·sqrt(3)/2          ∈ [−6Δ, +3Δ]           [m]
//   in-plane (k)       |s(deputy k, chief)| − L/2                ∈ [−Δ, +4Δ]            [m]
// (control box of paper sec. 1.1: in-plane inward −Δ, outward +4Δ; out-of-plane −6Δ, +3Δ).
#pragma once

#include <array>
#include <cstddef>
#include <string>
#include <vector>

#include "evade/core/constants.hpp"

namespace evade::formation {

/// Mean elements of a near-circular orbit (argument of latitude instead of ω and ν).
struct MeanElements {
  double a_m = 0.0;          ///< semi-major axis [m]
  double e = 0.0;            ///< eccentricity [-] (the geometry above assumes e << 1)
  double i_rad = 0.0;        ///< inclination [rad]
  double raan_rad = 0.0;     ///< right ascension of the ascending node [rad]
  double arg_lat_rad = 0.0;  ///< argument of latitude u = ω + ν [rad]
};

enum class Role { kChief = 0, kDeputy1 = 1, kDeputy2 = 2 };
const char* role_name(Role r);

struct Group {
  std::string name;
  std::array<MeanElements, 3> sats{};     ///< indexed by Role
  double nominal_raan_offset_rad = 0.0;   ///< nominal Ω_c,g − Ω_c,ref [rad]
  double nominal_phase_offset_rad = 0.0;  ///< nominal u_c,g − u_c,ref [rad]
};

struct SatelliteId {
  std::size_t group = 0;
  Role role = Role::kChief;
  bool operator==(const SatelliteId& o) const { return group == o.group && role == o.role; }
};

/// The whole constellation and its tolerances. validate() before use.
struct FormationSpec {
  double side_length_m = 0.0;        ///< L: side of the nominal equilateral triangle [m]
  double box_delta_m = 0.0;          ///< Δ: control-box unit [m]
  double raan_tolerance_rad = 0.0;   ///< Ω_max [rad]
  double phase_tolerance_rad = 0.0;  ///< Δφ_max [rad]
  double horizon_days = 0.0;         ///< T: time until the next formation-keeping burn [day]
  EarthModel earth = kEarthDefault;
  std::vector<Group> groups;
  std::size_t reference_group = 0;

  /// Throws std::invalid_argument naming the field, the value and the allowed range.
  void validate() const;
  const MeanElements& sat(const SatelliteId& id) const {
    return groups[id.group].sats[static_cast<std::size_t>(id.role)];
  }
  std::string sat_name(const SatelliteId& id) const;
};

enum class ConstraintKind { kInterGroupRaan, kInterGroupPhase, kOutOfPlane, kInPlane };
const char* constraint_kind_name(ConstraintKind k);

/// One row of Table 1: a quantity of the pair (first, second) and its allowed band.
struct ConstraintDef {
  ConstraintKind kind = ConstraintKind::kInPlane;
  std::string name;     ///< e.g. "in_plane_deputy1(F1)"
  SatelliteId first;    ///< the group chief (inter-group) or the deputy (intra-group)
  SatelliteId second;   ///< the reference chief (inter-group) or the chief (intra-group)
  double nominal = 0.0; ///< nominal value of the raw quantity [rad or m]
  double lower = 0.0;   ///< allowed deviation, lower edge [rad or m]
  double upper = 0.0;   ///< allowed deviation, upper edge [rad or m]
};

/// Table 1's rows for a maneuver of `threatened`: inter-group RAAN and phase of its group
/// against the reference group (of every other group when the threatened satellite is in
/// the reference group), out-of-plane and in-plane of each deputy of its group.
std::vector<ConstraintDef> constraints_for(const FormationSpec& spec, const SatelliteId& threatened);

/// Raw quantity of the constraint (before subtracting the nominal) from the pair's elements.
double raw_quantity(ConstraintKind kind, const MeanElements& first, const MeanElements& second);
/// Deviation from nominal (wrapped for angles).
double deviation(const ConstraintDef& c, const MeanElements& first, const MeanElements& second);
/// Distance to the nearer edge of the band (negative when outside).
double margin(const ConstraintDef& c, double deviation_value);

}  // namespace evade::formation
