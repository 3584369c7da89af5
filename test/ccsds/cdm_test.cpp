// CCSDS CDM (508.0-B-1): KVN -> model -> XML -> model round trip, ten malformed messages each
// rejected naming the keyword and the line, and the Pc of the shipped Alfano 2009 case 01
// CDM through the reader (NASA CARA Pc2D_Foster: 1.46749549e-01, relative tolerance 1e-3).
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include "evade/assessment/assess.hpp"
#include "evade/ccsds/cdm_kvn.hpp"
#include "evade/ccsds/cdm_xml.hpp"
#include "evade/assessment/covariance.hpp"

namespace evade::assessment {
namespace {

using namespace evade::ccsds;

std::string shipped() {
  std::ifstream in(std::string(EVADE_TEST_CDM_DIR) + "/alfano-2009-case01.cdm");
  std::ostringstream os;
  os << in.rdbuf();
  return os.str();
}

// Replaces the first line that starts with `key` by `with` (empty: deletes it).
std::string edit(const std::string& text, const std::string& key, const std::string& with) {
  std::istringstream in(text);
  std::string line, out;
  bool done = false;
  while (std::getline(in, line)) {
    if (!done && line.rfind(key, 0) == 0) {
      done = true;
      if (!with.empty()) out += with + "\n";
      continue;
    }
    out += line + "\n";
  }
  return out;
}

TEST(Cdm, KvnToXmlRoundTripIsIdentical) {
  const Cdm a = read_cdm_kvn(shipped());
  const std::string xml = write_cdm_xml(a);
  const Cdm b = read_cdm_xml(xml);
  EXPECT_TRUE(a == b);
  EXPECT_TRUE(read_cdm_kvn(write_cdm_kvn(b)) == a);
  EXPECT_EQ(cdm_value(b.object[1].additional_parameters, "MASS"), "500.0");
  EXPECT_EQ(b.object[0].covariance.items.size(), 28u);  // 21 + the 7 CDRG terms
  EXPECT_NE(xml.find("<relativeStateVector>"), std::string::npos);
}

// The CDM's two states and 6x6 covariances at TCA, HBR 15 m, assessed as given.
Assessment assess_at_tca(const Cdm& c) {
  ConjunctionInput in;
  in.hbr_m = 15.0;
  for (int i = 0; i < 2; ++i) {
    in.obj[i].state = cdm_state(c, i);
    in.obj[i].cov_eci = cov_eci_from_rtn(cdm_cov_rtn(c, i), in.obj[i].state);
    in.obj[i].has_velocity_cov = true;
  }
  AssessConfig cfg;
  cfg.tca_search_s = 0.0;
  return assess(in, cfg);
}

TEST(Cdm, PcOfShippedAlfanoCase01) {
  const double pc = pc_of(assess_at_tca(read_cdm_kvn(shipped())).plane_pc, PcMethod::k2d);
  EXPECT_NEAR(pc, 1.46749549e-01, 1e-3 * 1.46749549e-01);
}

// A negative eigenvalue only in the velocity block (CTDOT_RDOT^2 > CRDOT_RDOT CTDOT_TDOT) is an
// NPD covariance: the whole 6x6 is checked and repaired, and the repair is reported.
TEST(Cdm, VelocityBlockNpdIsFoundAndRepaired) {
  const Assessment a = assess_at_tca(
      read_cdm_kvn(edit(shipped(), "CTDOT_RDOT", "CTDOT_RDOT = -1.0e-04 [m**2/s**2]")));
  EXPECT_TRUE(a.npd[0]);
  EXPECT_LT(a.min_eigenvalue[0], 0.0);
  EXPECT_FALSE(a.npd[1]);
}

// A negative variance is malformed, not an NPD to repair: refused naming the keyword and line.
TEST(Cdm, NegativeVarianceIsRefusedNamingTheKeyword) {
  try {
    (void)read_cdm_kvn(edit(shipped(), "CR_R", "CR_R = -1.0 [m**2]"));
    ADD_FAILURE() << "a negative CR_R was accepted";
  } catch (const CdmError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("'CR_R'"), std::string::npos) << m;
    EXPECT_NE(m.find("line 39"), std::string::npos) << m;
    EXPECT_NE(m.find("variance cannot be negative"), std::string::npos) << m;
  }
}

struct Bad {
  const char* key;       // line to edit
  const char* with;      // replacement ("" deletes)
  const char* keyword;   // expected in the message
  const char* line;      // expected "line N"
};

TEST(Cdm, TenMalformedMessagesNameKeywordAndLine) {
  const Bad bad[] = {
      {"TCA ", "", "'TCA'", "line 103"},                                    // mandatory missing
      {"MISS_DISTANCE", "MISS_DISTANCE = 5.0x [m]", "'MISS_DISTANCE'", "line 7"},
      {"RELATIVE_SPEED", "RELATIVE_SPEED = 0.01 [km/s]", "'RELATIVE_SPEED'", "line 8"},
      {"CREATION_DATE", "CREATION_DATE = 2000-13-01T00:00:00", "'CREATION_DATE'", "line 3"},
      {"MANEUVERABLE", "MANEUVERABLE = MAYBE", "'MANEUVERABLE'", "line 23"},
      {"REF_FRAME", "REF_FRAME = TEME", "'REF_FRAME'", "line 24"},
      {"Y_DOT", "Y_DOT_DOT = 1 [km/s]", "'Y_DOT_DOT'", "line 37"},
      {"CT_T", "CT_T", "'CT_T'", "line 41"},                                // no '='
      {"OBJECT_NAME", "ORIGINATOR = ME", "'ORIGINATOR'", "line 19"},        // header after OBJECT
      {"CN_N", "", "'CN_N'", "line 103"},                                   // covariance term missing
  };
  for (const Bad& b : bad) {
    const std::string text = edit(shipped(), b.key, b.with);
    try {
      (void)read_cdm_kvn(text);
      ADD_FAILURE() << "accepted: " << b.key << " -> " << b.with;
    } catch (const CdmError& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find(b.keyword), std::string::npos) << m;
      EXPECT_NE(m.find(b.line), std::string::npos) << m;
    }
  }
}

// Units spelled as other implementations write them (Orekit: m**2/s/s, m**3/kg/s) are the
// standard's units: accepted, each listed by cdm_unit_notes; a different unit is still refused.
TEST(Cdm, EquivalentUnitSpellingsAreAcceptedAndNoted) {
  std::string text = edit(shipped(), "CRDOT_RDOT",
                          "CRDOT_RDOT = 3.761358714147070e-05 [m**2/s/s]");
  text = edit(text, "CRDOT_R ", "CRDOT_R = 2.675448519614438e-02 [m**2*s**-1]");
  const Cdm c = read_cdm_kvn(text);
  const std::vector<std::string> notes = cdm_unit_notes(c);
  ASSERT_EQ(notes.size(), 2u);
  EXPECT_NE(notes[0].find("CRDOT_R"), std::string::npos) << notes[0];
  EXPECT_NE(notes[1].find("[m**2/s/s] read as the standard's equivalent [m**2/s**2]"),
            std::string::npos)
      << notes[1];
  EXPECT_EQ(cdm_cov_rtn(c, 0), cdm_cov_rtn(read_cdm_kvn(shipped()), 0));
  EXPECT_THROW(read_cdm_kvn(edit(shipped(), "CRDOT_RDOT", "CRDOT_RDOT = 3.7e-05 [m**2/s]")),
               CdmError);
  EXPECT_TRUE(cdm_unit_notes(read_cdm_kvn(shipped())).empty());
}

// The unit reader: factors joined by '*' and '/', '**n' exponents in [-9, 9], one level of
// parentheses after '/', any case (an unclosed group or a trailing separator read leniently);
// a unit that differs, or text that is not a unit, is refused.
TEST(Cdm, UnitSpellingsOfACovarianceTerm) {
  const auto unit_ok = [](const std::string& unit) {
    try {
      (void)read_cdm_kvn(edit(shipped(), "CDRG_RDOT", "CDRG_RDOT = 0.0 [" + unit + "]"));
      return true;
    } catch (const CdmError& e) {
      EXPECT_NE(std::string(e.what()).find("expected unit [m**3/(kg*s)]"), std::string::npos)
          << e.what();
      return false;
    }
  };
  for (const char* u : {"m**3/(kg*s)", "M**3/KG/S", "m**3*kg**-1*s**-1", "kg**-1*m**3/s",
                        "m**3/(s*kg)", "m*m**2/(kg*s)", "m**4/(kg*s*m)", "m**3/(kg*s", "m**3/kg/s/"})
    EXPECT_TRUE(unit_ok(u)) << u;
  for (const char* u : {"m**3/kg", "m**3/(kg/(s))", "m**3/kg**10/s",
                        "m**3/(kg*s)/s", "m**/(kg*s)", "3/(kg*s)", "m**3/(kg*s*s)", "m^3/(kg*s)"})
    EXPECT_FALSE(unit_ok(u)) << u;
}

// Issue 46: a CDM's values reach JSON and Python strings. A Latin-1 value (0xC9) is read as
// 'E' acute in UTF-8, in KVN and XML alike; a control character is refused with line and
// column (it made `evade assess --cdm --json` exit 1 with the JSON library's type_error 316).
TEST(Cdm, Latin1ValuesAreReadAsUtf8AndControlCharactersRefusedWithLineAndColumn) {
  const std::string kvn = edit(shipped(), "MESSAGE_ID", "MESSAGE_ID = A09 \xC9");
  const Cdm a = read_cdm_kvn(kvn);
  EXPECT_EQ(cdm_value(a.header, "MESSAGE_ID"), "A09 \xC3\x89");
  const Cdm x = read_cdm_xml(write_cdm_xml(a));  // UTF-8 written, read back unchanged
  EXPECT_EQ(cdm_value(x.header, "MESSAGE_ID"), "A09 \xC3\x89");
  std::string latin1_xml = write_cdm_xml(a);
  latin1_xml.replace(latin1_xml.find("A09 \xC3\x89"), 6, "A09 \xC9");
  EXPECT_EQ(cdm_value(read_cdm_xml(latin1_xml).header, "MESSAGE_ID"), "A09 \xC3\x89");
  try {
    (void)read_cdm_kvn(edit(shipped(), "MESSAGE_ID", "MESSAGE_ID = A09\x1B"));
    ADD_FAILURE() << "a control character was accepted";
  } catch (const CdmError& e) {
    EXPECT_STREQ(e.what(), "CDM line 5, column 17: control character U+001B; expected printable "
                           "text (UTF-8 or Latin-1)");
  }
}

TEST(Cdm, MalformedXmlNamesElementAndLine) {
  std::string xml = write_cdm_xml(read_cdm_kvn(shipped()));
  const auto p = xml.find("<X units=\"km\">153.446765</X>");
  ASSERT_NE(p, std::string::npos);
  xml.replace(p, 29, "<X units=\"km\">abc</X>");
  try {
    (void)read_cdm_xml(xml);
    ADD_FAILURE() << "accepted";
  } catch (const CdmError& e) {
    EXPECT_NE(std::string(e.what()).find("'X'"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace evade::assessment
