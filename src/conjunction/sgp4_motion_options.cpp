// The checks of Sgp4MotionOptions (sgp4_motion.hpp): each field's range, the failure naming
// the field, its value and its range.
// SGP4 motion of a catalog for the screeners (issue 12; see sgp4_motion.hpp). SGP4/SDP4:
// Vallado, Crawford, Hujsak & Kelso (2006), AIAA 2006-6753 (evade/sgp4). Central and second
// differences: e.g. Atkinson, An Introduction to Numerical Analysis, 2nd ed., sec. 5.7.
// The perturbation envelope and what it assumes: docs/VALIDATION.md, "Robust mode with SGP4
// motion".
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "evade/conjunction/sgp4_motion.hpp"

namespace evade::conjunction {
namespace {

// Throws std::invalid_argument naming an Sgp4MotionOptions field, its value and its range.
[[noreturn]] void fail_option(const char* key, double v, const char* range) {
  std::ostringstream os;
  os << "sgp4 motion: " << key << " = " << v << " outside " << range;
  throw std::invalid_argument(os.str());
}

}  // namespace

void Sgp4MotionOptions::validate() const {
  if (!(span_s > 0.0) || !std::isfinite(span_s)) fail_option("span_s", span_s, "(0, inf)");
  if (!std::isfinite(start_j2000_s)) fail_option("start_j2000_s", start_j2000_s, "finite");
  if (threads < 1 || threads > 256) fail_option("threads", threads, "[1, 256]");
  if (!(envelope_block_gap_s >= 0.0) || !std::isfinite(envelope_block_gap_s))
    fail_option("envelope_block_gap_s", envelope_block_gap_s, "[0, inf)");
  validate_steps();
  validate_parts();
}

void Sgp4MotionOptions::validate_parts() const {
  if (parts < 1) fail_option("parts", parts, "[1, inf)");
  if (part < 0 || part >= parts) fail_option("part", part, "[0, parts)");
  if (parts > 1 && !sum_over_parts)
    throw std::invalid_argument("sgp4 motion: parts = " + std::to_string(parts) + " needs sum_over_parts");
}

void Sgp4MotionOptions::validate_steps() const {
  if (!(velocity_step_s > 0.0 && velocity_step_s <= 1.0))
    fail_option("velocity_step_s", velocity_step_s, "(0, 1]");
  if (!(accel_step_s > 0.0 && accel_step_s <= 10.0)) fail_option("accel_step_s", accel_step_s, "(0, 10]");
  if (samples_per_orbit < 8 || samples_per_orbit > 100000)
    fail_option("samples_per_orbit", samples_per_orbit, "[8, 100000]");
  if (max_samples < 2) fail_option("max_samples", static_cast<double>(max_samples), "[2, inf)");
  if (!(object_size_m >= 0.0) || !std::isfinite(object_size_m))
    fail_option("object_size_m", object_size_m, "[0, inf)");
  validate_envelope();
}

void Sgp4MotionOptions::validate_envelope() const {
  if (!(envelope_step_s > 0.0 && envelope_step_s <= 10.0))
    fail_option("envelope_step_s", envelope_step_s, "(0, 10]");
  if (!(envelope_factor >= 1.0) || !std::isfinite(envelope_factor))
    fail_option("envelope_factor", envelope_factor, "[1, inf)");
  if (!(envelope_floor_mps2 >= 0.0) || !std::isfinite(envelope_floor_mps2))
    fail_option("envelope_floor_mps2", envelope_floor_mps2, "[0, inf)");
}

}  // namespace evade::conjunction
