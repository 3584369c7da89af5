// The TLE/3LE reader (tle_reader.hpp): two- and three-line sets, Alpha-5 catalog numbers,
// and its error rules: a bad entry is rejected with line, column and what was expected, and
// the rest of the file is read. The OMM and GP forms: test/ccsds/catalog_formats_test.cpp.
#include <gtest/gtest.h>

#include <string>

#include "evade/sgp4/catalog.hpp"
#include "evade/sgp4/text_fields.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::sgp4 {
namespace {

// ISS (ZARYA), a well-formed TLE with valid checksums.
const std::string kIss1 = "1 25544U 98067A   08264.51782528 -.00002182  00000-0 -11606-4 0  2927";
const std::string kIss2 = "2 25544  51.6416 247.4627 0006703 130.5360 325.0288 15.72125391563537";

TEST(TleReader, ReadsTwoAndThreeLineSetsAndAlpha5) {
  const Catalog c = read_tle("ISS (ZARYA)\n" + kIss1 + "\n" + kIss2 + "\n", "iss.tle");
  ASSERT_EQ(c.objects.size(), 1u);
  EXPECT_EQ(c.objects[0].name, "ISS (ZARYA)");
  EXPECT_EQ(c.objects[0].norad_id, 25544);
  EXPECT_EQ(c.objects[0].epoch_year, 2008);
  EXPECT_DOUBLE_EQ(c.objects[0].bstar_per_er, -0.11606e-4);
  EXPECT_DOUBLE_EQ(c.objects[0].inclination_deg, 51.6416);
  long n = 0;
  // Alpha-5: A = 10, ..., H = 17, J = 18 (no I), ..., P = 23 (no O), Z = 33.
  ASSERT_TRUE(parse_alpha5("A0001", n));
  EXPECT_EQ(n, 100001);
  ASSERT_TRUE(parse_alpha5("J2345", n));
  EXPECT_EQ(n, 182345);
  ASSERT_TRUE(parse_alpha5("Z9999", n));
  EXPECT_EQ(n, 339999);
  EXPECT_FALSE(parse_alpha5("I0001", n));
}

TEST(TleReader, BadChecksumIsRejectedWithLineColumnAndTheRestIsRead) {
  std::string bad2 = kIss2;
  bad2[68] = bad2[68] == '0' ? '1' : '0';
  const std::string text = kIss1 + "\n" + bad2 + "\n" + kIss1 + "\n" + kIss2 + "\n";
  const Catalog c = read_tle(text, "two.tle");
  ASSERT_EQ(c.objects.size(), 1u);
  ASSERT_EQ(c.bad_entries, 1);
  EXPECT_EQ(c.issues[0].line, 2);
  EXPECT_EQ(c.issues[0].column, 69);
  EXPECT_NE(c.issues[0].message().find("two.tle:2:69: expected checksum 7"), std::string::npos)
      << c.issues[0].message();
}

TEST(TleReader, FieldErrorsNameTheColumn) {
  std::string l2 = kIss2;
  l2.replace(8, 8, "191.6416");  // inclination out of [0, 180]
  l2[68] = static_cast<char>('0' + tle_checksum(l2));
  const Catalog c = read_tle(kIss1 + "\n" + l2 + "\n", "f.tle");
  ASSERT_EQ(c.issues.size(), 1u);
  EXPECT_EQ(c.issues[0].column, 9);
  EXPECT_NE(c.issues[0].expected.find("inclination in [0, 180]"), std::string::npos);
  const Catalog d = read_tle(kIss1 + "\n", "g.tle");  // line 2 missing
  ASSERT_EQ(d.issues.size(), 1u);
  EXPECT_NE(d.issues[0].expected.find("line 2"), std::string::npos);
  std::string l1 = kIss1;
  l1.replace(20, 12, "08400.517825");  // day 400
  l1[68] = static_cast<char>('0' + tle_checksum(l1));
  const Catalog e = read_tle(l1 + "\n" + kIss2 + "\n", "e.tle");
  ASSERT_EQ(e.issues.size(), 1u);
  EXPECT_EQ(e.issues[0].column, 21);
}

// Issue 46: the title line is text that reaches JSON, CSV and Python strings. UTF-8 is kept;
// a title that is not UTF-8 is read as Latin-1 (ISO 8859-1, the encoding of older catalog
// exports), so 0xC9 is 'É'; a control character refuses the title with its line and column.
TEST(TleReader, TitleInUtf8IsKeptAndInLatin1IsDecodedToUtf8) {
  const Catalog u = read_tle("ISS \xC3\x89TOILE\n" + kIss1 + "\n" + kIss2 + "\n", "u.tle");
  ASSERT_EQ(u.objects.size(), 1u);
  EXPECT_EQ(u.objects[0].name, "ISS \xC3\x89TOILE");
  const Catalog l = read_tle("ISS \xC9TOILE \xFF\n" + kIss1 + "\n" + kIss2 + "\n", "l.tle");
  ASSERT_EQ(l.objects.size(), 1u);
  EXPECT_EQ(l.bad_entries, 0);
  EXPECT_EQ(l.objects[0].name, "ISS \xC3\x89TOILE \xC3\xBF");
  std::string out;
  EXPECT_EQ(title_to_utf8("\xE2\xA2", &out), 0);  // a cut UTF-8 sequence: Latin-1
  EXPECT_EQ(out, "\xC3\xA2\xC2\xA2");
  EXPECT_EQ(title_to_utf8("\xED\xA0\xBF", &out), 0);  // a UTF-16 surrogate is not UTF-8
  EXPECT_EQ(out, "\xC3\xAD\xC2\xA0\xC2\xBF");
  EXPECT_EQ(title_to_utf8("\xC0\xAF", &out), 0);  // an overlong '/' is not UTF-8 either
  EXPECT_EQ(out, "\xC3\x80\xC2\xAF");
}

TEST(TleReader, TitleWithAControlCharacterIsRefusedWithLineAndColumn) {
  const Catalog c = read_tle("ISS\x07 BELL\n" + kIss1 + "\n" + kIss2 + "\n", "c.tle");
  ASSERT_EQ(c.bad_entries, 1);
  EXPECT_EQ(c.issues[0].line, 1);
  EXPECT_EQ(c.issues[0].column, 4);
  EXPECT_NE(c.issues[0].message().find(
                "c.tle:1:4: expected a title of printable characters (UTF-8 or Latin-1), "
                "found 'U+0007'"),
            std::string::npos) << c.issues[0].message();
  ASSERT_EQ(c.objects.size(), 1u);  // the element set is read, without the refused title
  EXPECT_EQ(c.objects[0].name, "");
  std::string out;
  EXPECT_EQ(title_to_utf8("A\xC2\x85", &out), 2);  // U+0085 (NEL, a C1 control) in UTF-8
  EXPECT_EQ(title_to_utf8("AB\x85", &out), 3);      // the same in Latin-1
  EXPECT_EQ(title_to_utf8("A\x7F", &out), 2);
}

// Issue 46: an issue's found text is the file's own bytes; its message is printable UTF-8 (a
// Latin-1 byte in a field made `evade propagate --tle --json` write invalid JSON with exit 0).
TEST(TleReader, IssueMessagesArePrintableUtf8WhateverTheFileHeld) {
  std::string l1 = kIss1;
  l1[9] = '\xC9';  // a Latin-1 byte in the catalog number
  const Catalog c = read_tle(l1 + "\n" + kIss2 + "\n2 \xC9\x07 stray\n", "l\xE9.tle");
  ASSERT_EQ(c.bad_entries, 2);
  EXPECT_EQ(c.issues[1].message(),
            "l\xC3\xA9.tle:3:1: expected line 1 of an element set (starting '1 ') before line 2, "
            "found '2 \xC3\x89<U+0007> stray'");
  for (const ReadIssue& is : c.issues) {
    std::string out;
    EXPECT_EQ(title_to_utf8(is.message(), &out), 0) << "not printable UTF-8";
  }
  EXPECT_EQ(printable_utf8("A\xE2\x82\xAC\t"), "A\xE2\x82\xAC<U+0009>");  // UTF-8 kept
}

}  // namespace
}  // namespace evade::sgp4
