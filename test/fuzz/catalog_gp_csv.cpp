// Fuzz harness: the catalog reader evade/sgp4/gp_csv.hpp on any text (catalog_harness.hpp has
// the properties checked).
#include "catalog_harness.hpp"
#include "evade/sgp4/gp_csv.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_catalog_reader(data, size, [](const std::string& t) { return evade::sgp4::read_gp_csv(t, "fuzz"); });
  return 0;
}
