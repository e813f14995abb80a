// --json: the schema of issue 7, checked by parsing the output back.
#include <catch2/catch.hpp>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>

#include "Json.hpp"
#include "MiniJson.hpp"

using namespace cuetrack::bench;

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

void checkEntry(const minijson::Value& v, const std::string& tracker) {
  REQUIRE(v.kind == minijson::Value::Object);
  CHECK(v.keys() == std::vector<std::string>{"tracker", "config", "runs", "sequences", "average"});
  CHECK(v.get("tracker")->s == tracker);
  CHECK(v.get("runs")->n == 3);
  const minijson::Value* seqs = v.get("sequences");
  REQUIRE(seqs->kind == minijson::Value::Array);
  REQUIRE(seqs->items.size() == 2);
  for (const minijson::Value& s : seqs->items) {
    std::vector<std::string> want = {"name"};
    want.insert(want.end(), kFigureKeys.begin(), kFigureKeys.end());
    want.push_back("skipped_frames");
    CHECK(s.keys() == want);
    for (const char* k : {"overlap", "hit", "pascal"}) {
      const minijson::Value* p = s.get(k);
      if (p->kind == minijson::Value::Number) {
        CHECK(p->n >= 0);
        CHECK(p->n <= 100);  // percentages 0-100
      }
    }
  }
  CHECK(v.get("average")->keys() == kFigureKeys);
}

}  // namespace

TEST_CASE("one tracker: the file holds that object, with the schema's keys in order") {
  const std::string text = toJson({makeEntry("cuetrack", "1.1", true)});
  minijson::Value v;
  REQUIRE(minijson::parse(text, &v));
  checkEntry(v, "cuetrack");
  CHECK(v.get("config")->s == "1.1");
  const minijson::Value& s0 = v.get("sequences")->items[0];
  CHECK(s0.get("name")->s == "Vid_C_juice");
  CHECK(s0.get("frames")->n == 404);
  CHECK(s0.get("overlap")->n == Approx(80));
  CHECK(s0.get("pascal")->n == Approx(95.5));
  CHECK(s0.get("center_px")->n == Approx(4.25));
  // A name with quotes survives; a missing centre distance is null, not NaN.
  const minijson::Value& s1 = v.get("sequences")->items[1];
  CHECK(s1.get("name")->s == "seq \"two\"");
  CHECK(s1.get("center_px")->kind == minijson::Value::Null);
  // Frames the reader skipped as damaged are counted per sequence.
  CHECK(s0.get("skipped_frames")->n == 3);
  CHECK(s1.get("skipped_frames")->n == 0);
  // Millimetres with one decimal (docs/bench-json.md): rounded, not cut or left long.
  CHECK(text.find("\"center_mm\": 12.5, \"center_z_mm\": 3.3,") != std::string::npos);
  CHECK(s0.get("center_mm")->n == Approx(12.5));
  CHECK(s0.get("center_z_mm")->n == Approx(3.3));
  CHECK(s1.get("center_mm")->kind == minijson::Value::Null);
  CHECK(s1.get("center_z_mm")->kind == minijson::Value::Null);
  // Average: the macro mean of the sequences (80 and 60), centre over the one that has it.
  const minijson::Value* avg = v.get("average");
  CHECK(avg->get("overlap")->n == Approx(70));
  CHECK(avg->get("center_px")->n == Approx(4.25));
  CHECK(avg->get("center_mm")->n == Approx(12.5));
  CHECK(avg->get("frames")->n == 808);
}

TEST_CASE("several trackers: an array of those objects; a sequence not run has nulls") {
  const std::string text =
      toJson({makeEntry("cuetrack", "best", true), makeEntry("opencv-kcf", "default", false)});
  minijson::Value v;
  REQUIRE(minijson::parse(text, &v));
  REQUIRE(v.kind == minijson::Value::Array);
  REQUIRE(v.items.size() == 2);
  checkEntry(v.items[0], "cuetrack");
  checkEntry(v.items[1], "opencv-kcf");
  CHECK(v.items[1].get("config")->s == "default");
  const minijson::Value& notRun = v.items[1].get("sequences")->items[1];
  CHECK(notRun.get("frames")->n == 0);
  for (const char* k : {"overlap", "hit", "pascal", "center_px", "center_mm", "center_z_mm",
                        "ms_median", "ms_mean", "allocs"})
    CHECK(notRun.get(k)->kind == minijson::Value::Null);
  // The average covers only the sequence it ran on.
  CHECK(v.items[1].get("average")->get("overlap")->n == Approx(80));
}

TEST_CASE("writeJson writes the file and reports an unwritable path in one line") {
  const std::string path = "test_bench_json_out.json";
  std::string err;
  REQUIRE(writeJson(path.c_str(), {makeEntry("cuetrack", "1.1", true)}, &err));
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  minijson::Value v;
  CHECK(minijson::parse(ss.str(), &v));
  std::remove(path.c_str());

  CHECK_FALSE(writeJson("/nonexistent-dir/x.json", {makeEntry("cuetrack", "1.1", true)}, &err));
  CHECK(err.find("/nonexistent-dir/x.json") != std::string::npos);
  CHECK(err.find('\n') == std::string::npos);
}

TEST_CASE("the test's JSON reader holds numbers to JSON's grammar") {
  // Its strictness is what lets the schema checks above reject what a JSON parser would.
  for (const char* good : {"[0]", "[-0.5e3]", "[12.25]", "[1E+2]", "[-7]"}) {
    INFO(good);
    minijson::Value g;
    CHECK(minijson::parse(good, &g));
  }
  minijson::Value w;
  REQUIRE(minijson::parse("[-0.5e3]", &w));
  REQUIRE(w.items.size() == 1);
  CHECK(w.items[0].n == Approx(-500));
  for (const char* bad :
       {"[nan]", "[inf]", "[+1]", "[0x10]", "[01]", "[1.]", "[.5]", "[1e]", "[-]"}) {
    INFO(bad);
    minijson::Value b;
    CHECK_FALSE(minijson::parse(bad, &b));
  }
}
