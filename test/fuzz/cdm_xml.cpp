// Fuzz harness: the CDM reader evade/ccsds/cdm_xml.hpp on any text (cdm_harness.hpp has
// the properties checked).
#include "cdm_harness.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_cdm_reader(data, size,
                              [](const std::string& t) { return evade::ccsds::read_cdm_xml(t); });
  return 0;
}
