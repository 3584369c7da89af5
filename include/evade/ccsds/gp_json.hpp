// The JSON "GP" form catalogue providers serve: an array of objects (or one object) whose
// keys are the OMM keywords (OBJECT_NAME, EPOCH, MEAN_MOTION, ..., NORAD_CAT_ID, BSTAR).
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"

namespace evade::ccsds {

/// Reads every object; a bad value rejects its object (the issue gives the line and column
/// of the object's '{' and names the key). Values may be JSON numbers or strings. Keys that
/// are not OMM keywords (providers add their own, e.g. DECAY_DATE) are ignored.
sgp4::Catalog read_gp_json(const std::string& text, const std::string& source);

}  // namespace evade::ccsds
