// CCSDS OMM in XML (CCSDS 505.0-B-1 "XML Specification for Navigation Data Messages"): one
// or more <omm> (alone or inside <ndm>), each <segment> giving one entry: the leaf elements
// of <metadata>, <meanElements> and <tleParameters> are the OMM keywords.
#pragma once

#include <string>

#include "evade/sgp4/catalog.hpp"

namespace evade::ccsds {

/// Reads every OMM segment of an XML text with a small strict reader of the OMM subset:
/// elements, attributes, text, comments, the XML declaration and the five predefined
/// entities; no DTD, CDATA or other entities. A document that is not well formed gives
/// one issue at the first fault (line, column) and no entries from the rest of the file
/// (there is nothing to resynchronise on); a bad value rejects only its segment.
sgp4::Catalog read_omm_xml(const std::string& text, const std::string& source);

}  // namespace evade::ccsds
