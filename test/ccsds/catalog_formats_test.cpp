// The catalog forms of catalog_formats.hpp: OMM KVN and XML, GP JSON and CSV, on the same
// element set (Vanguard 1 as the OMM sample of the python3-sgp4 package and its TLE), the
// format detection, and the error rules: a bad entry is rejected with line, column and what
// was expected, the rest is read. The TLE reader: test/sgp4/tle_reader_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "evade/ccsds/catalog_formats.hpp"
#include "evade/ccsds/gp_csv.hpp"
#include "evade/ccsds/gp_json.hpp"
#include "evade/ccsds/omm_kvn.hpp"
#include "evade/ccsds/omm_xml.hpp"
#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/sgp4.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::ccsds {
namespace {

using sgp4::Catalog;
using sgp4::MeanElements;
using sgp4::Sgp4Error;
using sgp4::Sgp4Propagator;
using sgp4::Sgp4State;
using sgp4::read_tle;

// ISS (ZARYA), a well-formed TLE with valid checksums.
const std::string kIss1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
const std::string kIss2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

const std::string kKvn =
    "CCSDS_OMM_VERS = 2.0\nCREATION_DATE = 2020-10-13T12:00:00\nORIGINATOR = TEST\n"
    "OBJECT_NAME = VANGUARD 1\nOBJECT_ID = 1958-002B\nCENTER_NAME = EARTH\nREF_FRAME = TEME\n"
    "TIME_SYSTEM = UTC\nMEAN_ELEMENT_THEORY = SGP4\nEPOCH = 2020-10-13T04:52:48.472320\n"
    "MEAN_MOTION = 10.84869164 [rev/day]\nECCENTRICITY = .1845686\nINCLINATION = 34.2443 [deg]\n"
    "RA_OF_ASC_NODE = 225.5254\nARG_OF_PERICENTER = 162.2516\nMEAN_ANOMALY = 205.2356\n"
    "EPHEMERIS_TYPE = 0\nCLASSIFICATION_TYPE = U\nNORAD_CAT_ID = 5\nELEMENT_SET_NO = 999\n"
    "REV_AT_EPOCH = 21814\nBSTAR = -.22483E-4\nMEAN_MOTION_DOT = -1.6E-7\nMEAN_MOTION_DDOT = 0\n";

const std::string kXml =
    "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<ndm>\n<omm id=\"CCSDS_OMM_VERS\" version=\"2.0\">\n"
    "<header><CREATION_DATE/><ORIGINATOR/></header><body><segment><metadata>"
    "<OBJECT_NAME>VANGUARD 1</OBJECT_NAME><OBJECT_ID>1958-002B</OBJECT_ID><CENTER_NAME>EARTH</CENTER_NAME>"
    "<REF_FRAME>TEME</REF_FRAME><TIME_SYSTEM>UTC</TIME_SYSTEM><MEAN_ELEMENT_THEORY>SGP4</MEAN_ELEMENT_THEORY>"
    "</metadata><data><meanElements><EPOCH>2020-10-13T04:52:48.472320</EPOCH><MEAN_MOTION>10.84869164</MEAN_MOTION>"
    "<ECCENTRICITY>.1845686</ECCENTRICITY><INCLINATION>34.2443</INCLINATION><RA_OF_ASC_NODE>225.5254</RA_OF_ASC_NODE>"
    "<ARG_OF_PERICENTER>162.2516</ARG_OF_PERICENTER><MEAN_ANOMALY>205.2356</MEAN_ANOMALY></meanElements>"
    "<tleParameters><EPHEMERIS_TYPE>0</EPHEMERIS_TYPE><CLASSIFICATION_TYPE>U</CLASSIFICATION_TYPE>"
    "<NORAD_CAT_ID>5</NORAD_CAT_ID><ELEMENT_SET_NO>999</ELEMENT_SET_NO><REV_AT_EPOCH>21814</REV_AT_EPOCH>"
    "<BSTAR>-.22483E-4</BSTAR><MEAN_MOTION_DOT>-1.6E-7</MEAN_MOTION_DOT><MEAN_MOTION_DDOT>0</MEAN_MOTION_DDOT>"
    "</tleParameters></data></segment></body></omm>\n</ndm>\n";

const std::string kCsvHeader =
    "OBJECT_NAME,OBJECT_ID,EPOCH,MEAN_MOTION,ECCENTRICITY,INCLINATION,RA_OF_ASC_NODE,ARG_OF_PERICENTER,"
    "MEAN_ANOMALY,EPHEMERIS_TYPE,CLASSIFICATION_TYPE,NORAD_CAT_ID,ELEMENT_SET_NO,REV_AT_EPOCH,BSTAR,"
    "MEAN_MOTION_DOT,MEAN_MOTION_DDOT\n";
const std::string kCsvRow =
    "VANGUARD 1,1958-002B,2020-10-13T04:52:48.472320,10.84869164,.1845686,34.2443,225.5254,162.2516,"
    "205.2356,0,U,5,999,21814,-.22483E-4,-1.6E-7,0\n";

const std::string kJson =
    "[{\"OBJECT_NAME\":\"VANGUARD 1\",\"OBJECT_ID\":\"1958-002B\",\"EPOCH\":\"2020-10-13T04:52:48.472320\","
    "\"MEAN_MOTION\":10.84869164,\"ECCENTRICITY\":0.1845686,\"INCLINATION\":34.2443,\"RA_OF_ASC_NODE\":225.5254,"
    "\"ARG_OF_PERICENTER\":162.2516,\"MEAN_ANOMALY\":205.2356,\"EPHEMERIS_TYPE\":0,\"CLASSIFICATION_TYPE\":\"U\","
    "\"NORAD_CAT_ID\":5,\"ELEMENT_SET_NO\":999,\"REV_AT_EPOCH\":21814,\"BSTAR\":-2.2483e-05,"
    "\"MEAN_MOTION_DOT\":-1.6e-07,\"MEAN_MOTION_DDOT\":0,\"DECAY_DATE\":null}]";

void expect_vanguard(const Catalog& c) {
  ASSERT_EQ(c.objects.size(), 1u);
  ASSERT_TRUE(c.issues.empty()) << c.issues[0].message();
  const MeanElements& m = c.objects[0];
  EXPECT_EQ(m.norad_id, 5);
  EXPECT_EQ(m.name, "VANGUARD 1");
  EXPECT_EQ(m.epoch_year, 2020);
  // 2020-10-13 is day 287 of a leap year; 04:52:48.472320 = 0.203338800 day.
  EXPECT_NEAR(m.epoch_day_of_year, 287.0 + (4 * 3600 + 52 * 60 + 48.47232) / 86400.0, 1e-11);
  EXPECT_DOUBLE_EQ(m.mean_motion_revpday, 10.84869164);
  EXPECT_DOUBLE_EQ(m.eccentricity, 0.1845686);
  EXPECT_DOUBLE_EQ(m.bstar_per_er, -2.2483e-5);
}

TEST(CatalogReader, AllOmmFormsGiveTheSameElements) {
  expect_vanguard(read_omm_kvn(kKvn, "v.kvn"));
  expect_vanguard(read_omm_xml(kXml, "v.xml"));
  expect_vanguard(read_gp_csv(kCsvHeader + kCsvRow, "v.csv"));
  expect_vanguard(read_gp_json(kJson, "v.json"));
  EXPECT_EQ(detect_catalog_format(kKvn), CatalogFormat::kOmmKvn);
  EXPECT_EQ(detect_catalog_format(kXml), CatalogFormat::kOmmXml);
  EXPECT_EQ(detect_catalog_format(kCsvHeader), CatalogFormat::kGpCsv);
  EXPECT_EQ(detect_catalog_format(kJson), CatalogFormat::kGpJson);
  EXPECT_EQ(detect_catalog_format(kIss1), CatalogFormat::kTle);
}

TEST(OmmReaders, BadValuesAreRejectedWithLineAndKeyword) {
  std::string kvn = kKvn + kKvn;
  const std::size_t p = kvn.rfind("ECCENTRICITY = .1845686");
  kvn.replace(p, 23, "ECCENTRICITY = 1.5");
  const Catalog c = read_omm_kvn(kvn, "b.kvn");
  ASSERT_EQ(c.objects.size(), 1u);
  ASSERT_EQ(c.issues.size(), 1u);
  EXPECT_EQ(c.issues[0].line, 24 + 12);  // ECCENTRICITY is line 12 of each message
  EXPECT_EQ(c.issues[0].column, 16);
  EXPECT_NE(c.issues[0].expected.find("ECCENTRICITY"), std::string::npos);
  std::string xml = kXml;
  xml.replace(xml.find("</EPOCH>"), 8, "</EPOCHX>");
  const Catalog x = read_omm_xml(xml, "b.xml");
  ASSERT_EQ(x.issues.size(), 1u);
  EXPECT_EQ(x.issues[0].line, 4);
  EXPECT_NE(x.issues[0].expected.find("</EPOCH>"), std::string::npos);
  const Catalog j = read_gp_json("[" + kJson.substr(1, kJson.size() - 2) + ",{\"NORAD_CAT_ID\":7}]", "b.json");
  ASSERT_EQ(j.objects.size(), 1u);
  ASSERT_EQ(j.issues.size(), 1u);
  EXPECT_NE(j.issues[0].expected.find("EPOCH"), std::string::npos);
  const Catalog v = read_gp_csv(kCsvHeader + kCsvRow + "X,1,2020-13-01T00:00:00,1,0,0,0,0,0,0,U,9,1,1,0,0,0\n", "b.csv");
  ASSERT_EQ(v.objects.size(), 1u);
  ASSERT_EQ(v.issues.size(), 1u);
  EXPECT_EQ(v.issues[0].line, 3);
  EXPECT_EQ(v.issues[0].column, 5);
}

// Issue 46: OBJECT_NAME and OBJECT_ID reach JSON, CSV and Python strings: kept in UTF-8, read as
// Latin-1 when not UTF-8 (0xC9 is 'E' acute), refused at their line and column with a control.
TEST(OmmReaders, NamesInLatin1AreDecodedAndControlCharactersRefused) {
  std::string kvn = kKvn;
  kvn.replace(kvn.find("VANGUARD 1"), 10, "VANGUARD \xC9");
  const Catalog c = read_omm_kvn(kvn, "l.kvn");
  ASSERT_EQ(c.objects.size(), 1u);
  EXPECT_EQ(c.objects[0].name, "VANGUARD \xC3\x89");
  kvn = kKvn;
  kvn.replace(kvn.find("VANGUARD 1"), 10, "VANGUARD\x1B" "1");
  const Catalog e = read_omm_kvn(kvn, "e.kvn");
  ASSERT_EQ(e.objects.size(), 0u);
  ASSERT_EQ(e.issues.size(), 1u);
  EXPECT_EQ(e.issues[0].line, 4);
  EXPECT_EQ(e.issues[0].column, 15);
  EXPECT_EQ(e.issues[0].message(),
            "e.kvn:4:15: expected OBJECT_NAME of printable characters (UTF-8 or Latin-1), "
            "found 'U+001B'");
}

// Found by fuzzing (docs/ASSURANCE.md): a JSON number beyond double made the JSON parser
// throw out_of_range (not a parse error), which escaped read_gp_json. It is now one issue
// naming the number's line and column, like any other malformed JSON.
TEST(OmmReaders, JsonNumberBeyondDoubleIsAnIssueNotAnException) {
  const std::string json = "[{\"OBJECT_NAME\":\"X\",\n \"MEAN_MOTION\":1e999}]";
  Catalog c;
  ASSERT_NO_THROW(c = read_gp_json(json, "big.json"));
  EXPECT_TRUE(c.objects.empty());
  ASSERT_EQ(c.issues.size(), 1u);
  EXPECT_EQ(c.bad_entries, 1);
  EXPECT_EQ(c.issues[0].line, 2);
  EXPECT_EQ(c.issues[0].column, 16);
  EXPECT_EQ(c.issues[0].found, "1e999");
  EXPECT_NE(c.issues[0].expected.find("within the range of a double"), std::string::npos);
}

TEST(OmmReaders, OmmAndTleOfTheSameSetPropagateAlike) {
  // Vanguard 1 as a TLE (the package's sample): same state as the OMM to the rounding of
  // the epoch (the OMM gives microseconds, the TLE 1e-8 day = 0.86 ms).
  const Catalog t = read_tle(
      "1 00005U 58002B   20287.20333880 -.00000016  00000-0 -22483-4 0  9998\n"
      "2 00005  34.2443 225.5254 1845686 162.2516 205.2356 10.84869164218149\n", "v.tle");
  ASSERT_EQ(t.objects.size(), 1u) << (t.issues.empty() ? "" : t.issues[0].message());
  const Catalog o = read_omm_kvn(kKvn, "v.kvn");
  const Sgp4Propagator a(t.objects[0]), b(o.objects[0]);
  ASSERT_EQ(a.init_error(), Sgp4Error::kNone);
  const double dt_s = (epoch_seconds_since_j2000(o.objects[0]) - epoch_seconds_since_j2000(t.objects[0]));
  EXPECT_LT(std::abs(dt_s), 1e-3);
  const Sgp4State sa = a.propagate_s(3600.0), sb = b.propagate_s(3600.0 - dt_s);
  EXPECT_LT((sa.r_teme_m - sb.r_teme_m).norm(), 0.05);
}

}  // namespace
}  // namespace evade::ccsds
