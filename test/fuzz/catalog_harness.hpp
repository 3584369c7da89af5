// Fuzz harness core for the catalog readers (src/sgp4: TLE/3LE, OMM KVN and XML, GP JSON and
// CSV). The readers' contract (catalog.hpp): never throw, never stop at the first bad entry,
// never drop an entry silently. Checked for any text (abort on violation):
//   - no exception escapes the reader;
//   - one issue per rejected entry (issues.size() == bad_entries), each with a non-empty
//     message naming a line >= 0 and a column >= 0;
//   - every accepted entry has finite elements, and SGP4 initialises from it and propagates
//     90 minutes without a crash or UB, its state finite whenever it reports no error.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <exception>
#include <string>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "fuzz_check.hpp"

namespace evade::fuzz {

inline constexpr std::size_t kMaxPropagated = 8;  // entries propagated per input

inline void check_elements(const sgp4::MeanElements& m) {
  EVADE_FUZZ_CHECK(std::isfinite(m.epoch_day_of_year) && std::isfinite(m.mean_motion_revpday) &&
                       std::isfinite(m.eccentricity) && std::isfinite(m.inclination_deg) &&
                       std::isfinite(m.raan_deg) && std::isfinite(m.arg_perigee_deg) &&
                       std::isfinite(m.mean_anomaly_deg) && std::isfinite(m.bstar_per_er) &&
                       std::isfinite(m.mean_motion_dot_revpday2) &&
                       std::isfinite(m.mean_motion_ddot_revpday3),
                   "accepted entry has finite elements");
  const sgp4::Sgp4Propagator prop(m);
  for (const double t_min : {0.0, 90.0}) {
    const sgp4::Sgp4State s = prop.propagate_min(t_min);
    if (s.error == sgp4::Sgp4Error::kNone)
      EVADE_FUZZ_CHECK(s.r_teme_m.allFinite() && s.v_teme_mps.allFinite(),
                       "SGP4 state finite when no error is reported");
  }
}

template <typename Reader>
void run_catalog_reader(const std::uint8_t* data, std::size_t size, Reader read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  sgp4::Catalog cat;
  try {
    cat = read(text);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "exception escaped the catalog reader: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "a non-std exception escaped the catalog reader\n");
    std::abort();
  }
  EVADE_FUZZ_CHECK(static_cast<std::size_t>(cat.bad_entries) == cat.issues.size(),
                   "one issue per rejected entry");
  for (const sgp4::ReadIssue& i : cat.issues) {
    EVADE_FUZZ_CHECK(i.line >= 0 && i.column >= 0, "issue line and column >= 0");
    EVADE_FUZZ_CHECK(!i.message().empty(), "issue message");
  }
  for (std::size_t k = 0; k < cat.objects.size() && k < kMaxPropagated; ++k)
    check_elements(cat.objects[k]);
}

}  // namespace evade::fuzz
