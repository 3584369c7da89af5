// Fuzz harness: the catalog reader evade/ccsds/gp_json.hpp on any text (catalog_harness.hpp has
// the properties checked).
#include "catalog_harness.hpp"
#include "evade/ccsds/gp_json.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_catalog_reader(data, size, [](const std::string& t) { return evade::ccsds::read_gp_json(t, "fuzz"); });
  return 0;
}
