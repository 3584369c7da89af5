// CDM in XML form (CCSDS 505.0-B-1 NDM/XML, schema ndmxml-1.0-cdm-1.0.xsd): <cdm id=
// "CCSDS_CDM_VERS" version=".."> with <header>, <body> holding <relativeMetadataData> (the
// relative state inside <relativeStateVector>) and two <segment>s of <metadata> and <data>
// (<odParameters>, <additionalParameters>, <stateVector>, <covarianceMatrix>); units as
// units="..". The reader is a small XML parser (elements, attributes, text, comments, the
// declaration; entities &amp; &lt; &gt; &quot; &apos;) that maps the tree onto the model of
// cdm.hpp and validates it; errors name the element (keyword) and the line.
#pragma once

#include <string>

#include "evade/ccsds/cdm.hpp"

namespace evade::ccsds {

Cdm read_cdm_xml(const std::string& text);
std::string write_cdm_xml(const Cdm& cdm);

}  // namespace evade::ccsds
