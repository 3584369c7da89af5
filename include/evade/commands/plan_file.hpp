// The burn-plan file: what `evade plan observability|threat-area|formation --plan-out FILE`
// write and `evade sim --plan FILE` loads into a run. It holds exactly what the uplink
// message evade_burn_plan_t carries for execution (plan id, frame, impulses with their time
// after the plan's epoch and Δv in RSW and, when known, ECI), as JSON:
//
//   {
//     "format": "evade.burn_plan.v1",
//     "plan_id": 1,
//     "source": "formation",            // threat-area | formation | observability | collision-avoidance | unknown
//     "frame": "rsw",                   // rsw | eci: the Δv the node flies
//     "impulses": [
//       {"t_s": 43200.0, "dv_rsw_mps": [6.2e-07, 0.0058078, 0.0],
//        "dv_eci_mps": [-0.0020016, 0.0048526, 0.0024852]},   // optional (null or absent)
//       ...
//     ]
//   }
//
// Times are seconds after the plan's epoch (t = 0); the epoch itself is chosen when the plan
// is flown (the uplink's epoch_utime, or the run's start plus an offset in the simulator).
// Reading validates at the edge and names the field: unknown keys, wrong types, a format
// other than v1, NaN/Inf (numbers as strings, or overflowing to Inf), |t| > 1e9 s, 1..8
// impulses, times not strictly increasing, a frame other than rsw/eci, frame eci with an
// impulse lacking its ECI Δv. The observability planner's extras (ε, θ, objective) are not
// part of the file: the node does not fly them.
#pragma once

#include <string>

#include "evade/core/burn_plan.hpp"
#include "evade/guidance/plan_executor.hpp"

namespace evade::commands {

inline constexpr const char* kPlanFileFormat = "evade.burn_plan.v1";

struct PlanFile {
  BurnPlan plan;  ///< plan_id, source, impulses (no observability block)
  guidance::PlanFrame frame = guidance::PlanFrame::kRsw;
};

/// The file's JSON text (2-space indent, each double in the shortest form that reads back
/// bit-exact). Throws std::invalid_argument naming the field if the plan cannot be written
/// as a valid file (the reader's rules).
std::string plan_file_json(const PlanFile& f);

/// The plan file's name of a BurnPlan source code ("threat-area", "formation",
/// "observability", "collision-avoidance", "unknown"); std::invalid_argument for another code.
const char* plan_source_name(int code);

/// Parses and validates text; source names it in errors ("plan file 'x.json': ...").
/// Throws std::invalid_argument naming the field, the value and what is allowed.
PlanFile parse_plan_file(const std::string& text, const std::string& source);

/// Reads path (std::invalid_argument if it cannot be opened, or as parse_plan_file).
PlanFile read_plan_file(const std::string& path);

/// Writes path (std::invalid_argument if it cannot be written, or as plan_file_json).
void write_plan_file(const std::string& path, const PlanFile& f);

}  // namespace evade::commands
