// Fuzz harness core for the CCSDS CDM readers (src/assessment: KVN and XML, CCSDS 508.0-B-1).
// The readers' contract (cdm.hpp): a malformed or incomplete message throws CdmError naming
// the keyword and the line; anything else is a bug. Checked for any text (abort on
// violation):
//   - only CdmError leaves the reader, with a non-empty message;
//   - an accepted message passes validate_cdm, gives both objects' state and RTN covariance
//     without throwing, and survives the documented round trips unchanged: KVN -> model ->
//     KVN -> model and model -> XML -> model (operator== on the model).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "evade/ccsds/cdm.hpp"
#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"
#include "fuzz_check.hpp"

namespace evade::fuzz {

[[noreturn]] inline void escaped(const char* where, const char* what) {
  std::fprintf(stderr, "fuzz property violated: %s threw something other than CdmError: %s\n",
               where, what);
  std::abort();
}

inline void check_accepted_cdm(const ccsds::Cdm& cdm) {
  try {
    ccsds::validate_cdm(cdm);
    for (int i = 0; i < 2; ++i) {
      (void)ccsds::cdm_state(cdm, i);
      (void)ccsds::cdm_cov_rtn(cdm, i);
    }
    const ccsds::Cdm kvn = ccsds::read_cdm_kvn(ccsds::write_cdm_kvn(cdm));
    EVADE_FUZZ_CHECK(kvn == cdm, "KVN round trip leaves the message unchanged");
    const ccsds::Cdm xml = ccsds::read_cdm_xml(ccsds::write_cdm_xml(cdm));
    EVADE_FUZZ_CHECK(xml == cdm, "XML round trip leaves the message unchanged");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz property violated: an accepted CDM failed later: %s\n", e.what());
    std::abort();
  }
}

template <typename Reader>
void run_cdm_reader(const std::uint8_t* data, std::size_t size, Reader read) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  ccsds::Cdm cdm;
  try {
    cdm = read(text);
  } catch (const ccsds::CdmError& e) {
    EVADE_FUZZ_CHECK(e.what()[0] != '\0', "CdmError has a message");
    return;
  } catch (const std::exception& e) {
    escaped("the CDM reader", e.what());
  } catch (...) {
    escaped("the CDM reader", "(not a std::exception)");
  }
  check_accepted_cdm(cdm);
}

}  // namespace evade::fuzz
