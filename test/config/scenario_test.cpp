// Scenario reading: every bad value names its key, its value and what is allowed.
#include <gtest/gtest.h>

#include <cmath>

#include "evade/config/scenario.hpp"

namespace evade::config {
namespace {

const char* kDoc = R"(
sensor:
  noise_rad: 5.0e-5
  rate_hz: 50
  mode: angles-only
target:
  r_eci_m: [1.0, 2.0, 3.0]
objects:
  - {a_m: 7.0e6, size_m: 1.0}
  - {a_m: 7.1e6, size_m: 3.0}
)";

std::string error_of(const std::function<void()>& f) {
  try {
    f();
  } catch (const ConfigError& e) {
    return e.what();
  }
  return "<no error>";
}

TEST(Scenario, ReadsTypedValuesWithRanges) {
  const Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  EXPECT_DOUBLE_EQ(s.get_double("sensor.noise_rad", 0.0, 1.0), 5.0e-5);
  EXPECT_EQ(s.get_int("sensor.rate_hz", 1, 1000), 50);
  EXPECT_EQ(s.get_enum("sensor.mode", {"ideal", "angles-only"}), "angles-only");
  EXPECT_EQ(s.get_vec3("target.r_eci_m", -1e9, 1e9), Vec3(1, 2, 3));
  EXPECT_EQ(s.list_size("objects"), 2u);
  EXPECT_DOUBLE_EQ(s.get_double("objects.1.size_m", 0.0, 100.0), 3.0);
  EXPECT_DOUBLE_EQ(s.get_double("absent_key_s", 0.0, 10.0, 4.0), 4.0);
}

TEST(Scenario, OutOfRangeValueNamesKeyValueAndRange) {
  const Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  const std::string msg = error_of([&] { s.get_double("sensor.noise_rad", 0.0, 1e-5); });
  EXPECT_NE(msg.find("sensor.noise_rad"), std::string::npos) << msg;
  EXPECT_NE(msg.find("5.0e-5"), std::string::npos) << msg;
  EXPECT_NE(msg.find("[0, 1e-05]"), std::string::npos) << msg;
}

TEST(Scenario, RejectsNanInfAndNonNumbers) {
  for (const char* bad : {"nan", ".nan", "inf", "-.inf", "1e999", "12abc", "[1,2]"}) {
    Scenario s = Scenario::from_yaml_string(kDoc, "doc");
    s.apply_override(std::string("sensor.noise_rad=") + bad);
    const std::string msg = error_of([&] { s.get_double("sensor.noise_rad", 0.0, 1.0); });
    EXPECT_NE(msg.find("sensor.noise_rad"), std::string::npos) << bad << ": " << msg;
  }
}

// Found by fuzzing (docs/ASSURANCE.md): a byte that is not UTF-8 reached a value, and the
// error text built from it threw nlohmann::json's type_error instead of a ConfigError. The
// text is now refused on reading, naming the line, the column and the byte; valid UTF-8
// (2-, 3- and 4-byte forms) still reads.
TEST(Scenario, TextThatIsNotUtf8IsAConfigErrorNamingTheByte) {
  const std::string file_msg =
      error_of([] { Scenario::from_yaml_string("a: 1\nb: [7\xCF\xCF, 0]\n", "f.yaml"); });
  EXPECT_NE(file_msg.find("f.yaml: line 2, column 6: not UTF-8 text (byte 0xCF)"),
            std::string::npos) << file_msg;
  for (const char* bad : {"k=\xC0\xAF", "k=\xED\xA0\x80", "k=\xF4\x90\x80\x80", "k=\xE2\x82"}) {
    Scenario s = Scenario::from_yaml_string(kDoc, "doc");
    const std::string msg = error_of([&] { s.apply_override(bad); });
    EXPECT_NE(msg.find("--set: line 1, column 3: not UTF-8 text"), std::string::npos) << msg;
  }
  Scenario s = Scenario::from_yaml_string("name: \"caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9B\xB0\"\n", "u.yaml");
  EXPECT_EQ(s.get_string("name"), "caf\xC3\xA9 \xE2\x82\xAC \xF0\x9F\x9B\xB0");
  s.apply_override("name=\xC3\xA9t\xC3\xA9");
  EXPECT_EQ(s.get_string("name"), "\xC3\xA9t\xC3\xA9");
}

// Fuzz finding 9: a --set value starting 01 00 00 00 made yaml-cpp read it as UTF-32 and
// decode code points beyond U+10FFFF, which escaped as nlohmann's type_error 316 when an
// error message quoted the value. Control characters other than tab, LF and CR are not YAML
// text (YAML 1.2 sec. 5.1): refused at the edge, naming the byte.
TEST(Scenario, ControlCharactersAreAConfigErrorNamingTheByte) {
  const std::string file_msg =
      error_of([] { Scenario::from_yaml_string(std::string("a: 1\nb: x\0y\n", 12), "f.yaml"); });
  EXPECT_NE(file_msg.find("f.yaml: line 2, column 5: a control character (byte 0x00)"),
            std::string::npos) << file_msg;
  const std::string utf32 = std::string("weights=\x01\0\0\0\x1d\x1d\x1d\x1d", 16);
  Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  const std::string msg = error_of([&] { s.apply_override(utf32); });
  EXPECT_NE(msg.find("--set: line 1, column 9: a control character (byte 0x01)"),
            std::string::npos) << msg;
  for (const char* bad : {"k=a\x7f", "k=\x1b[31m"}) {
    const std::string m = error_of([&] { s.apply_override(bad); });
    EXPECT_NE(m.find("a control character"), std::string::npos) << m;
  }
  // Escapes decode to the same: a double-quoted "\x01" is a control character too.
  const std::string esc = error_of([] { Scenario::from_yaml_string("a: \"x\\x01\"\n", "e.yaml"); });
  EXPECT_NE(esc.find("e.yaml: line 1, column 4: the scalar, decoded, is not text"),
            std::string::npos) << esc;
  s.apply_override("name=tab\there");  // tab, LF and CR stay allowed
  EXPECT_EQ(s.get_string("name"), "tab\there");
}

TEST(Scenario, UnknownKeyIsReportedWithTheAllowedKeys) {
  Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  s.apply_override("sensor.noise=1e-4");  // missing unit suffix
  s.get_double("sensor.noise_rad", 0.0, 1.0);
  s.get_int("sensor.rate_hz", 1, 1000);
  s.get_string("sensor.mode");
  s.get_vec3("target.r_eci_m", -1e9, 1e9);
  for (std::size_t i = 0; i < s.list_size("objects"); ++i) {
    s.get_double("objects." + std::to_string(i) + ".a_m", 0, 1e9);
    s.get_double("objects." + std::to_string(i) + ".size_m", 0, 1e3);
  }
  const std::string msg = error_of([&] { s.check_all_used(); });
  EXPECT_NE(msg.find("unknown key 'sensor.noise'"), std::string::npos) << msg;
  // The allowed keys beside it, not the whole document's.
  EXPECT_NE(msg.find("allowed keys under 'sensor': mode, noise_rad, rate_hz)"), std::string::npos) << msg;
  EXPECT_EQ(msg.find("r_eci_m"), std::string::npos) << msg;
}

TEST(Scenario, OverridesReplaceAndAddKeysAndIndexLists) {
  Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  s.apply_override("sensor.rate_hz=200");
  s.apply_override("objects.0.size_m=2.5");
  s.apply_override("new.block.value_s=3");
  s.apply_override("target.r_eci_m=[4, 5, 6]");
  EXPECT_EQ(s.get_int("sensor.rate_hz", 1, 1000), 200);
  EXPECT_DOUBLE_EQ(s.get_double("objects.0.size_m", 0, 10), 2.5);
  EXPECT_DOUBLE_EQ(s.get_double("new.block.value_s", 0, 10), 3.0);
  EXPECT_EQ(s.get_vec3("target.r_eci_m", -10, 10), Vec3(4, 5, 6));
  EXPECT_THROW(s.apply_override("objects.7.size_m=1"), ConfigError);
  EXPECT_THROW(s.apply_override("no_equals_sign"), ConfigError);
}

TEST(Scenario, WrongShapesAndMissingRequiredKeysAreErrors) {
  const Scenario s = Scenario::from_yaml_string(kDoc, "doc");
  EXPECT_THROW(s.get_vec3("sensor.noise_rad", 0, 1), ConfigError);
  EXPECT_THROW(s.get_double("sensor", 0, 1), ConfigError);
  EXPECT_THROW(s.get_double("missing_m", 0, 1), ConfigError);
  EXPECT_THROW(s.get_enum("sensor.mode", {"ideal"}), ConfigError);
  EXPECT_THROW(s.get_int("sensor.noise_rad", 0, 10), ConfigError);
  EXPECT_THROW(Scenario::from_yaml_string("a: [1, 2", "broken"), ConfigError);
  EXPECT_THROW(Scenario::from_yaml_string("- 1\n- 2\n", "list"), ConfigError);
  EXPECT_THROW(Scenario::load("no-such-scenario-name"), ConfigError);
}

}  // namespace
}  // namespace evade::config
