// The collision-probability methods, listed once (pc_methods()): each row names a method the
// way every output names it and says how it takes part in an assessment.
//   plane methods (from_plane): computed by every assessment from the encounter plane alone
//     (assess.hpp: Assessment::plane_pc, in table order);
//   escalation steps (escalate): walked in table order by choose_pc (pc_method_choice.hpp),
//     which recommends the first whose usage checks hold; a step without checks is the last
//     resort. A step marked every_method also runs beside an earlier recommendation when the
//     caller asks for every method (`evade assess`).
// The outputs are written from the rows: the JSON's "pc_<name>" and "pc_<name>_<figure>" and
// "usage"."pc_<name>", the text's labels, the CDM's COLLISION_PROBABILITY_METHOD. A new method
// is its own file (the computation, and its step when it takes part in the escalation) and
// one row here.
//
// Methods: 2D, Foster & Estes 1992 (quadrature, pc_2d.hpp); Chan 2008 eq. 5.33 (series); the
// maximum Pc of Alfano 2005; 3D-Nc, Hall 2021 (pc_3d_nc.hpp); the Monte Carlo from 6x6
// covariances (monte_carlo_pc.hpp).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "evade/assessment/pc_2d.hpp"

namespace evade::assessment {

enum class PcMethod : std::uint8_t { k2d, kChan, kMax, k3dNc, kMc };

/// A figure a method reports beside its Pc ("abs_error", "scale", "low", "high").
struct PcFigure {
  const char* name;
  double value;
};

/// One method's Pc as every output reports it (NaN: undefined).
struct PcValue {
  PcMethod method = PcMethod::k2d;
  double pc = 0.0;
  std::vector<PcFigure> figures;  ///< the row's figures, in its order
};

/// One usage check of a method (Hall, Baars, Casali, AAS 23-398, 2023).
struct UsageFlag {
  std::string name;        ///< "extended", "offset", "npd", "short_term", "converged"
  double value = 0.0;      ///< the indicator [-]
  double threshold = 0.0;  ///< violated when value > threshold [-]
  bool violated = false;
  std::string meaning;     ///< one line for the text output
};

/// One step of the escalation as it ran: the method's Pc and its usage checks.
struct PcStep {
  PcValue value;
  std::vector<UsageFlag> usage;  ///< empty for a step without checks (the last resort)
  bool checks_hold = true;       ///< no usage check is violated
};

struct PcStepInput;  // pc_method_choice.hpp
struct PcChoice;     // pc_method_choice.hpp

struct PcMethodRow {
  PcMethod id;
  const char* name;       ///< "2d": "method" and the JSON keys "pc_2d", "pc_2d_<figure>"
  const char* label;      ///< "2D": the text's name
  const char* cdm_code;   ///< COLLISION_PROBABILITY_METHOD when recommended (nullptr: never)
  std::array<const char*, 2> figures;  ///< names of the figures it reports (nullptr: none)
  /// A plane method: its Pc from the principal-axes encounter and the hard-body radius.
  PcValue (*from_plane)(const PrincipalEncounter& pe, double hbr_m, double rel_tol);
  /// An escalation step: runs the method on the assessment (its details into *c).
  PcStep (*escalate)(const PcStepInput& in, PcChoice* c);
  const char* check_noun;    ///< "usage check" (the reason text); nullptr: no checks
  bool needs_six_by_six;     ///< the step needs both 6x6 covariances
  bool every_method;         ///< the step runs beside an earlier recommendation on request
};

/// Every method, in the order of the escalation and of the outputs.
const std::vector<PcMethodRow>& pc_methods();
/// The row of m.
const PcMethodRow& pc_method(PcMethod m);
/// The row named name ("3d_nc"), or nullptr.
const PcMethodRow* pc_method_named(const std::string& name);

/// Every plane method's value (table order), or NaN values when the plane is undefined.
std::vector<PcValue> plane_pc_values(const PrincipalEncounter& pe, double hbr_m, double rel_tol);
std::vector<PcValue> undefined_plane_pc_values();
/// The value of m in values (NaN when it is not there).
double pc_of(const std::vector<PcValue>& values, PcMethod m);

}  // namespace evade::assessment
