// Fuzz harness: the scenario YAML reader with --set overrides (evade/config/scenario.hpp,
// read_params.hpp). Input: a YAML document; the lines after a line "#--set" are overrides
// "key.path=value", applied in order as `--set` applies them. Then what the guidance node
// and the simulator read: guidance.*, node.* (the parameter tables), earth.*, and typed reads
// of vectors, strings, enums, seeds and lists, and check_all_used().
// The reader's contract: bad input throws ConfigError naming the key, the value and what is
// allowed. Checked: no other exception escapes (a yaml-cpp or JSON exception, std::stod's
// out_of_range, ...), ConfigError messages are non-empty, and every value read is within the
// range the read asked for.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <vector>

#include "evade/config/read_params.hpp"
#include "evade/config/scenario.hpp"
#include "evade/core/earth_params.hpp"
#include "evade/guidance/guidance_params.hpp"
#include "evade/guidance_lcm/node_params.hpp"
#include "fuzz_check.hpp"

namespace {

using evade::config::Scenario;

void split(const std::string& text, std::string* yaml, std::vector<std::string>* sets) {
  const std::string marker = "#--set\n";
  std::size_t at = text.rfind(marker, 0) == 0 ? 0 : text.find("\n" + marker);
  if (at == std::string::npos) {
    *yaml = text;
    return;
  }
  const std::size_t start = at == 0 ? marker.size() : at + 1 + marker.size();
  *yaml = text.substr(0, at);
  std::size_t pos = start;
  while (pos < text.size() && sets->size() < 16) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    sets->push_back(text.substr(pos, nl - pos));
    pos = nl + 1;
  }
}

void read_everything(const Scenario& sc) {
  evade::guidance_lcm::NodeConfig node;
  evade::config::read_params(sc, "guidance.", evade::guidance::guidance_params(), &node.guidance);
  evade::config::read_params(sc, "node.", evade::guidance_lcm::node_params(), &node);
  const evade::EarthModel earth = evade::config::read_earth(sc);
  EVADE_FUZZ_CHECK(std::isfinite(earth.mu_m3ps2) && earth.mu_m3ps2 > 0.0, "earth mu in range");
  EVADE_FUZZ_CHECK(std::isfinite(node.guidance.max_accel_mps2), "guidance values finite");
  if (sc.has("satellite.r_eci_m")) {
    const evade::Vec3 r = sc.get_vec3("satellite.r_eci_m", -1e9, 1e9);
    EVADE_FUZZ_CHECK(r.allFinite() && r.cwiseAbs().maxCoeff() <= 1e9, "vec3 within its range");
  }
  const double s = sc.get_double("encounter.search_s", 0.0, 1e6, 60.0);
  EVADE_FUZZ_CHECK(s >= 0.0 && s <= 1e6, "double within its range");
  const long n = sc.get_int("sensor.n", -5, 5, 0);
  EVADE_FUZZ_CHECK(n >= -5 && n <= 5, "int within its range");
  (void)sc.get_string("description", "");
  (void)sc.get_enum("gravity", {"two_body", "two_body_j2"}, "two_body_j2");
  (void)sc.get_seed("sensor.seed", 1);
  (void)sc.get_bool("sensor.has_rates", false);
  const std::size_t objects = sc.list_size("objects");
  for (std::size_t i = 0; i < objects && i < 4; ++i) {
    const std::string key = "objects." + std::to_string(i) + ".a_m";
    if (sc.has(key)) (void)sc.get_double(key, 6.0e6, 5.0e7);
  }
  if (sc.has("weights")) {
    const std::vector<double> w = sc.get_double_list("weights", 0.0, 1.0);
    for (double x : w) EVADE_FUZZ_CHECK(x >= 0.0 && x <= 1.0, "list value within its range");
  }
  sc.check_all_used();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::string yaml;
  std::vector<std::string> sets;
  split(text, &yaml, &sets);
  try {
    Scenario sc = Scenario::from_yaml_string(yaml, "fuzz.yaml");
    for (const std::string& a : sets) sc.apply_override(a);
    read_everything(sc);
  } catch (const evade::config::ConfigError& e) {
    EVADE_FUZZ_CHECK(e.what()[0] != '\0', "ConfigError has a message");
  } catch (const std::exception& e) {
    std::fprintf(stderr, "fuzz property violated: not a ConfigError: %s\n", e.what());
    std::abort();
  } catch (...) {
    std::fprintf(stderr, "fuzz property violated: a non-std exception escaped\n");
    std::abort();
  }
  return 0;
}
