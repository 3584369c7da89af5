// CCSDS Conjunction Data Message (CCSDS 508.0-B-1, Blue Book, June 2013): the message model,
// its keyword tables and checks, and typed access to the states and RTN covariances.
//
// The model keeps every keyword of the message as text, in order, in its section (header;
// relative metadata/data; per object: metadata, OD parameters, additional parameters, state
// vector, covariance), so optional sections and comments survive a round trip KVN -> model
// -> XML -> model unchanged. validate_cdm checks what 508.0-B-1 requires: every mandatory
// keyword of tables 3-2 to 3-6 present once, numbers and epochs well formed, units (when
// given) those of the standard, OBJECT1 then OBJECT2, the enumerated values (REF_FRAME,
// MANEUVERABLE, COVARIANCE_METHOD, ...). Errors name the keyword and the line (CdmError).
// Units: positions km, velocities km/s (the standard's), converted to m, m/s by cdm_state.
#pragma once

#include <array>
#include <stdexcept>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "evade/core/state.hpp"

namespace evade::ccsds {

/// A malformed or incomplete CDM: "CDM line L: keyword 'K': <what was expected>".
class CdmError : public std::invalid_argument {
 public:
  using std::invalid_argument::invalid_argument;
};

struct CdmItem {
  std::string key;    ///< keyword, or "COMMENT"
  std::string value;  ///< text as written (trimmed)
  std::string unit;   ///< unit as written in [..] (KVN) or units="" (XML), may be empty
  int line = 0;       ///< source line (not compared)
  bool operator==(const CdmItem& o) const {
    return key == o.key && value == o.value && unit == o.unit;
  }
};

struct CdmSection {
  std::vector<CdmItem> items;
  const CdmItem* find(const std::string& key) const;
  bool operator==(const CdmSection& o) const { return items == o.items; }
};

enum class CdmSectionId { kHeader, kRelative, kMetadata, kOd, kAdditional, kState, kCovariance };

struct CdmObject {
  CdmSection metadata, od_parameters, additional_parameters, state_vector, covariance;
  CdmSection& section(CdmSectionId id);
  const CdmSection& section(CdmSectionId id) const;
  bool operator==(const CdmObject& o) const;
};

struct Cdm {
  CdmSection header;    ///< CCSDS_CDM_VERS, CREATION_DATE, ORIGINATOR, MESSAGE_FOR, MESSAGE_ID
  CdmSection relative;  ///< TCA, MISS_DISTANCE, relative state, screening volume, Pc
  std::array<CdmObject, 2> object;
  bool operator==(const Cdm& o) const;
};

/// The section a keyword belongs to (kHeader for CCSDS_CDM_VERS, ...). False if unknown.
bool cdm_keyword_section(const std::string& key, CdmSectionId* id);
/// The unit the standard gives a keyword ("" for none).
std::string cdm_keyword_unit(const std::string& key);
/// Keywords of a section in the standard's order.
const std::vector<std::string>& cdm_section_keywords(CdmSectionId id);

/// The text of a CDM (KVN or XML) as UTF-8, as the readers take it: valid UTF-8 is kept, any
/// other text is read as Latin-1 (ISO 8859-1) and written as UTF-8, so that every value reaches
/// JSON and Python as valid text. A control character other than tab, CR and LF throws
/// CdmError "CDM line L, column C: control character U+XXXX; expected printable text (UTF-8 or
/// Latin-1)".
std::string cdm_text_as_utf8(const std::string& text);

/// Throws CdmError naming the keyword and line of the first problem. A unit spelled
/// differently from the standard but equal to it (m**3/kg/s for m**3/(kg*s), the spelling of
/// other implementations) is accepted: cdm_unit_notes lists each such item.
void validate_cdm(const Cdm& cdm);
/// One note per item whose unit is an equivalent spelling of the standard's (validated CDMs).
std::vector<std::string> cdm_unit_notes(const Cdm& cdm);

/// Object i's (0 or 1) state in its REF_FRAME [m, m/s].
StateEci cdm_state(const Cdm& cdm, int i);
/// Object i's 6x6 position-velocity covariance in its RTN frame [m^2, m^2/s, m^2/s^2].
Mat6 cdm_cov_rtn(const Cdm& cdm, int i);
/// Object i's covariance rows present: 0-5 (R, T, N, RDOT, TDOT, NDOT), then 6 (DRG), 7 (SRP)
/// and 8 (THR) when the message gives their diagonal term.
std::vector<int> cdm_cov_rows(const Cdm& cdm, int i);
/// Object i's whole covariance over those rows (6x6, up to 9x9) in RTN, SI units; an
/// off-diagonal term the message leaves out is 0.
Eigen::MatrixXd cdm_cov_rtn_full(const Cdm& cdm, int i);
/// One note per object whose covariance with drag/SRP/thrust rows (7x7 to 9x9) is not
/// positive definite.
std::vector<std::string> cdm_covariance_notes(const Cdm& cdm);
/// A keyword's value (empty when absent).
std::string cdm_value(const CdmSection& s, const std::string& key);

}  // namespace evade::ccsds
