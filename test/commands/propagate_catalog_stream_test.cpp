// `evade propagate --tle/--omm` written as it goes (commands/propagate_catalog_stream.hpp): the
// streamed JSON document is the in-memory result's JSON (to_json(run_propagate_catalog)),
// number for number, on the Vallado et al. 2006 verification set (SGP4-VER.TLE, which has
// objects that stop at an SGP4 error inside the span) with tasks cut inside objects; the CSV
// and the summaries hold the same states; one thread and two write the same bytes; memory
// stays bounded.
#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

#include <nlohmann/json.hpp>

#include "evade/commands/propagate_catalog_stream.hpp"
#include "evade/sgp4/tle_reader.hpp"

namespace evade::commands {

using sgp4::Sgp4Error;
using sgp4::read_tle;
namespace {

PropagateCatalogRequest verification_request(double span_s, double step_s, const char* frame) {
  // The verification file's lines carry CR and, on line 2, the test's start/stop/step
  // columns after column 69: the element sets are the first 69 columns of lines 1 and 2.
  std::ifstream in(EVADE_TEST_SGP4_VER_TLE);
  std::string line, text;
  while (std::getline(in, line))
    if (line.size() >= 69 && (line[0] == '1' || line[0] == '2')) text += line.substr(0, 69) + "\n";
  PropagateCatalogRequest req;
  req.catalog = read_tle(text, "SGP4-VER.TLE");
  req.span_s = span_s;
  req.step_s = step_s;
  req.frame = frame;
  return req;
}

std::string streamed(const PropagateCatalogRequest& req, StateFormat f, int threads,
                     StreamedCatalog* summary = nullptr) {
  std::string out;
  const StreamedCatalog r = stream_propagate_catalog(
      req, f, threads, [&out](const char* d, std::size_t n) { out.append(d, n); });
  if (summary) *summary = r;
  return out;
}

// 1 day at 30 s: 2881 instants, two tasks per object (kStreamChunkSteps = 2048).
TEST(PropagateCatalogStream, JsonIsTheInMemoryResult) {
  static_assert(kStreamChunkSteps < 2881, "the test must cut objects into several tasks");
  for (const char* frame : {"teme", "eci"}) {
    const PropagateCatalogRequest req = verification_request(86400.0, 30.0, frame);
    StreamedCatalog s;
    const nlohmann::json got = nlohmann::json::parse(streamed(req, StateFormat::kJson, 2, &s));
    const nlohmann::json want = to_json(run_propagate_catalog(req));
    EXPECT_EQ(got, want) << frame;  // doubles compared exactly: shortest round-trip text
    int stopped = 0;
    for (const StreamedTrack& t : s.objects) stopped += t.error != Sgp4Error::kNone;
    EXPECT_GT(stopped, 0) << "the verification set has objects that stop inside a day";
    EXPECT_EQ(s.objects.size(), want["objects"].size());
    EXPECT_GE(s.objects.size(), 25u);
  }
}

TEST(PropagateCatalogStream, CsvHoldsTheSameStates) {
  const PropagateCatalogRequest req = verification_request(86400.0, 60.0, "teme");
  const PropagateCatalogResult mem = run_propagate_catalog(req);
  StreamedCatalog s;
  std::istringstream csv(streamed(req, StateFormat::kCsv, 2, &s));
  std::string line;
  std::getline(csv, line);
  EXPECT_EQ(line, "id,t_s,teme_x_m,teme_y_m,teme_z_m,teme_vx_mps,teme_vy_mps,teme_vz_mps");
  long rows = 0;
  for (const CatalogTrack& t : mem.objects) {
    for (const CatalogState& st : t.states) {
      ASSERT_TRUE(std::getline(csv, line));
      long id = 0;
      double v[7];
      ASSERT_EQ(std::sscanf(line.c_str(), "%ld,%lf,%lf,%lf,%lf,%lf,%lf,%lf", &id, &v[0], &v[1],
                            &v[2], &v[3], &v[4], &v[5], &v[6]),
                8);
      EXPECT_EQ(id, t.id);
      EXPECT_EQ(v[0], st.t_s);
      for (int i = 0; i < 3; ++i) EXPECT_EQ(v[1 + i], st.r_m(i));
      for (int i = 0; i < 3; ++i) EXPECT_EQ(v[4 + i], st.v_mps(i));
      ++rows;
    }
  }
  EXPECT_FALSE(std::getline(csv, line));
  EXPECT_EQ(rows, s.states);
}

TEST(PropagateCatalogStream, OneThreadAndTwoWriteTheSameBytes) {
  const PropagateCatalogRequest req = verification_request(86400.0, 30.0, "teme");
  EXPECT_EQ(streamed(req, StateFormat::kJson, 1), streamed(req, StateFormat::kJson, 2));
  EXPECT_EQ(streamed(req, StateFormat::kCsv, 1), streamed(req, StateFormat::kCsv, 3));
}

// The summaries alone (the text output): each object's count, last state and SGP4 error
// are the in-memory track's.
TEST(PropagateCatalogStream, SummariesAreTheInMemoryTracks) {
  const PropagateCatalogRequest req = verification_request(86400.0, 600.0, "teme");
  StreamedCatalog s;
  EXPECT_TRUE(streamed(req, StateFormat::kNone, 2, &s).empty());
  const PropagateCatalogResult mem = run_propagate_catalog(req);
  ASSERT_EQ(s.objects.size(), mem.objects.size());
  for (std::size_t i = 0; i < s.objects.size(); ++i) {
    const StreamedTrack& a = s.objects[i];
    const CatalogTrack& b = mem.objects[i];
    EXPECT_EQ(a.id, b.id);
    ASSERT_EQ(a.states, static_cast<long>(b.states.size())) << a.id;
    if (a.states > 0) {
      EXPECT_EQ(a.last.t_s, b.states.back().t_s);
      EXPECT_EQ(a.last.r_m, b.states.back().r_m);
    }
    EXPECT_EQ(a.error, b.error);
    EXPECT_EQ(a.error_t_s, b.error_t_s);
  }
  EXPECT_EQ(s.start_j2000_s, mem.start_j2000_s);
}

// The sink receives the output in pieces no larger than one wave of tasks' text: nothing
// accumulates with the number of instants (1 day at 1 s: 86401 instants per object).
TEST(PropagateCatalogStream, PiecesDoNotGrowWithTheSpan) {
  PropagateCatalogRequest req = verification_request(86400.0, 1.0, "teme");
  req.catalog.objects.resize(2);
  std::size_t largest = 0, total = 0;
  (void)stream_propagate_catalog(req, StateFormat::kCsv, 2,
                                 [&](const char*, std::size_t n) {
                                   largest = std::max(largest, n);
                                   total += n;
                                 });
  EXPECT_GT(total, 2u * 50u * 86401u);  // both objects' instants, > 50 bytes each  // every instant written, ~120 bytes each
  EXPECT_LT(largest, 200u * static_cast<std::size_t>(kStreamChunkSteps));
}

}  // namespace
}  // namespace evade::commands
