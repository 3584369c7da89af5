// Fuzz harness: the TLE/3LE reader evade/sgp4/tle_reader.hpp on any text, with the default
// options (what `evade propagate --tle` uses) and with the verification-set options
// (checksums not checked, text after column 69 allowed), so the deep-space verification
// elements reach SGP4 too. catalog_harness.hpp has the properties checked.
#include "catalog_harness.hpp"
#include "evade/sgp4/tle_reader.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  evade::fuzz::run_catalog_reader(
      data, size, [](const std::string& t) { return evade::sgp4::read_tle(t, "fuzz.tle"); });
  evade::sgp4::TleReadOptions verification;
  verification.check_checksum = false;
  verification.allow_trailing_text = true;
  evade::fuzz::run_catalog_reader(data, size, [&](const std::string& t) {
    return evade::sgp4::read_tle(t, "fuzz.tle", verification);
  });
  return 0;
}
