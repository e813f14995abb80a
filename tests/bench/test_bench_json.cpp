// --json: the schema of issue 7, checked by parsing the output back (nlohmann-json,
// strict: NaN, a trailing comma or a bad escape fail to parse).
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>

#include "BenchJsonSample.hpp"
#include "Json.hpp"
#include "TestPaths.hpp"

using namespace cuetrack::bench;
using Json = nlohmann::ordered_json;  // keeps the file's key order

namespace {

const std::vector<std::string> kFigureKeys = {
    "frames",         "overlap",      "hit",     "pascal",   "center_px", "center_mm",
    "center_z_mm",    "ms_median",    "ms_mean", "allocs",   "auc",       "precision20",
    "overlap_spread", "overlap_runs", "success", "precision"};

EntryResult makeEntry(const std::string& tracker, const std::string& config, bool secondRan) {
  EntryResult e;
  e.tracker = tracker;
  e.config = config;
  e.runs = 3;
  SequenceResult a;
  a.name = "Vid_C_juice";
  a.ran = true;
  a.figures.frames = 404;
  a.figures.overlap = 80;
  a.figures.hit = 100;
  a.figures.pascal = 95.5;
  a.figures.centerPx = 4.25;
  a.figures.centerMm = 12.46;  // written with one decimal: 12.5
  a.figures.centerZMm = 3.27;  // 3.3
  a.figures.msMedian = 1.5;
  a.figures.msMean = 2.0;
  a.figures.allocs = 0;
  a.skippedFrames = 3;
  SequenceResult b = a;
  b.skippedFrames = 0;
  b.name = "seq \"two\"";
  b.figures.overlap = 60;
  b.figures.centerPx = std::nan("");
  b.figures.centerMm = b.figures.centerZMm = std::nan("");  // no 3D truth
  b.ran = secondRan;
  if (!secondRan) b.error = "cannot run: no colour";
  e.sequences = {a, b};
  return e;
}

std::vector<std::string> keys(const Json& o) {
  std::vector<std::string> k;
  for (const auto& item : o.items()) k.push_back(item.key());
  return k;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

void checkEntry(const Json& v, const std::string& tracker) {
  REQUIRE(v.is_object());
  CHECK(keys(v) == std::vector<std::string>{"tracker", "config", "runs", "sequences", "average"});
  CHECK(v["tracker"] == tracker);
  CHECK(v["runs"] == 3);
  CHECK(v["runs"].is_number_integer());
  const Json& seqs = v["sequences"];
  REQUIRE(seqs.is_array());
  REQUIRE(seqs.size() == 2);
  for (const Json& s : seqs) {
    std::vector<std::string> want = {"name"};
    want.insert(want.end(), kFigureKeys.begin(), kFigureKeys.end());
    want.push_back("skipped_frames");
    CHECK(keys(s) == want);
    CHECK(s["frames"].is_number_integer());
    CHECK(s["skipped_frames"].is_number_integer());
    for (const char* k : {"overlap", "hit", "pascal"}) {
      if (s[k].is_number()) {
        CHECK(s[k].get<double>() >= 0);
        CHECK(s[k].get<double>() <= 100);  // percentages 0-100
      }
    }
  }
  CHECK(keys(v["average"]) == kFigureKeys);
}

}  // namespace

TEST_CASE("one tracker: the file holds that object, with the schema's keys in order") {
  const std::string text = toJson({makeEntry("cuetrack", "1.1", true)});
  const Json v = Json::parse(text);
  checkEntry(v, "cuetrack");
  CHECK(v["config"] == "1.1");
  const Json& s0 = v["sequences"][0];
  CHECK(s0["name"] == "Vid_C_juice");
  CHECK(s0["frames"] == 404);
  CHECK(s0["overlap"].get<double>() == Approx(80));
  CHECK(s0["pascal"].get<double>() == Approx(95.5));
  CHECK(s0["center_px"].get<double>() == Approx(4.25));
  // A name with quotes survives; a missing centre distance is null, not NaN.
  const Json& s1 = v["sequences"][1];
  CHECK(s1["name"] == "seq \"two\"");
  CHECK(s1["center_px"].is_null());
  // Frames the reader skipped as damaged are counted per sequence.
  CHECK(s0["skipped_frames"] == 3);
  CHECK(s1["skipped_frames"] == 0);
  // Millimetres with one decimal (docs/bench-json.md): rounded, not cut or left long.
  CHECK(s0["center_mm"].get<double>() == 12.5);
  CHECK(s0["center_z_mm"].get<double>() == 3.3);
  CHECK(s1["center_mm"].is_null());
  CHECK(s1["center_z_mm"].is_null());
  // Average: the macro mean of the sequences (80 and 60), centre over the one that has it.
  const Json& avg = v["average"];
  CHECK(avg["overlap"].get<double>() == Approx(70));
  CHECK(avg["center_px"].get<double>() == Approx(4.25));
  CHECK(avg["center_mm"].get<double>() == 12.5);
  CHECK(avg["frames"] == 808);
}

TEST_CASE("several trackers: an array of those objects; a sequence not run has nulls") {
  const std::string text =
      toJson({makeEntry("cuetrack", "best", true), makeEntry("opencv-kcf", "default", false)});
  const Json v = Json::parse(text);
  REQUIRE(v.is_array());
  REQUIRE(v.size() == 2);
  checkEntry(v[0], "cuetrack");
  checkEntry(v[1], "opencv-kcf");
  CHECK(v[1]["config"] == "default");
  const Json& notRun = v[1]["sequences"][1];
  CHECK(notRun["frames"] == 0);
  for (const char* k : {"overlap", "hit", "pascal", "center_px", "center_mm", "center_z_mm",
                        "ms_median", "ms_mean", "allocs"})
    CHECK(notRun[k].is_null());
  // The average covers only the sequence it ran on.
  CHECK(v[1]["average"]["overlap"].get<double>() == Approx(80));
}

TEST_CASE("writeJson writes the file and reports an unwritable path in one line") {
  const std::string path = "test_bench_json_out.json";
  std::string err;
  REQUIRE(writeJson(path.c_str(), {makeEntry("cuetrack", "1.1", true)}, &err));
  CHECK_NOTHROW(Json::parse(readAll(path)));
  std::remove(path.c_str());

  CHECK_FALSE(writeJson("/nonexistent-dir/x.json", {makeEntry("cuetrack", "1.1", true)}, &err));
  CHECK(err.find("/nonexistent-dir/x.json") != std::string::npos);
  CHECK(err.find('\n') == std::string::npos);
}

TEST_CASE("the file holds the values the hand-written writer wrote, key for key") {
  // data/bench-json-v1.json: the sample's file from the writer before nlohmann-json (the
  // layout differs, not a key, an order, a null or a value). Both are parsed and written
  // back in one form, so an integer that became 404.0 or a 3-decimal figure that became
  // another double fails here.
  const Json before =
      Json::parse(readAll(CUETRACK_SOURCE_DIR "/tests/bench/data/bench-json-v1.json"));
  const Json now = Json::parse(toJson(sample::entries()));
  CHECK(now.dump() == before.dump());
  CHECK(now == before);
  // One entry: the object alone, as before.
  const Json one = Json::parse(toJson({sample::entries().front()}));
  CHECK(one.dump() == before[0].dump());
}

TEST_CASE("a name that is not UTF-8 is written with U+FFFD, not a failure") {
  EntryResult e = makeEntry("cuetrack", "1.1", true);
  e.sequences[0].name = "caf\xe9";  // Latin-1
  const Json v = Json::parse(toJson({e}));
  CHECK(v["sequences"][0]["name"] == "caf\xef\xbf\xbd");
}
