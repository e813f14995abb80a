// fakenect recordings: synthetic -> writer -> reader round trip, libfreenect's exact
// file layout, pairing, bad input (one line naming the file) and no allocation per frame.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>

#include "AllocCounter.hpp"
#include "TempDir.hpp"
#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;
using cuetrack::test::TempDir;

namespace {

// Writes `frames` frames of a scene as a fakenect recording.
void writeScene(const std::string& dir, const char* scene, int frames, uint64_t seed = 3) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  spec.frameCount = frames;
  auto src = std::make_unique<SyntheticSource>(spec, seed);
  auto slot = std::make_unique<FrameSlot>();
  FakenectWriter w;
  if (!(w.open(dir.c_str(), scene))) FAIL(w.error());
  while (src->next(*slot) == ReadStatus::Ok)
    if (!(w.write(*slot))) FAIL(w.error());
  if (!(w.close())) FAIL(w.error());
  CHECK(w.framesWritten() == frames);
}

std::string firstEntry(const std::string& dir, char kind) {
  const std::string index = cuetrack::test::readText(dir + "/INDEX.txt");
  size_t pos = 0;
  while (pos < index.size()) {
    const size_t nl = index.find('\n', pos);
    const std::string line = index.substr(pos, nl - pos);
    if (!line.empty() && line[0] == kind) return line;
    pos = nl + 1;
  }
  return "";
}

}  // namespace

TEST_CASE("synthetic -> fakenect -> reader keeps colour, depth, truth and time", "[fakenect]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "occlusion", 6);

  SceneSpec spec;
  REQUIRE(makeScene("occlusion", &spec));
  spec.frameCount = 6;
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto want = std::make_unique<FrameSlot>();
  auto got = std::make_unique<FrameSlot>();
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 6);
  CHECK(std::string(reader.name()) == "rec");
  int n = 0;
  while (reader.next(*got) == ReadStatus::Ok) {
    REQUIRE(src->next(*want) == ReadStatus::Ok);
    CHECK(got->index == n);
    CHECK(got->timeUs == want->timeUs);
    REQUIRE(got->rgb.width() == 640);
    REQUIRE(got->rgb.height() == 480);
    CHECK(std::memcmp(got->rgb.data(), want->rgb.data(), 640 * 480 * 3) == 0);
    REQUIRE(got->hasDepth);
    int maxErr = 0, holesDiffer = 0;
    for (int i = 0; i < 640 * 480; ++i) {
      const int a = got->depthMm.data()[i], b = want->depthMm.data()[i];
      holesDiffer += (a == 0) != (b == 0);
      maxErr = std::max(maxErr, std::abs(a - b));
    }
    CHECK(holesDiffer == 0);
    // Synthetic depth is already on the raw grid: the round trip is exact; the bound
    // that holds for any depth is half a raw step (~0.5 * 0.0031 z^2, 100 mm at 8 m).
    CHECK(maxErr == 0);
    CHECK(got->hasGroundTruth == want->hasGroundTruth);
    CHECK(got->groundTruth.empty() == want->groundTruth.empty());
    CHECK(got->groundTruth.x == Approx(want->groundTruth.x).margin(1e-3));
    CHECK(got->groundTruth.y == Approx(want->groundTruth.y).margin(1e-3));
    CHECK(got->groundTruth.w == Approx(want->groundTruth.w).margin(1e-3));
    CHECK(got->groundTruth.h == Approx(want->groundTruth.h).margin(1e-3));
    CHECK(got->intrinsics.fx == Approx(kKinectV1Intrinsics.fx));
    ++n;
  }
  CHECK(n == 6);
  CHECK(reader.next(*got) == ReadStatus::End);
}

TEST_CASE("fakenect files have libfreenect's exact layout", "[fakenect]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 2);
  const std::string d = firstEntry(dir, 'd'), r = firstEntry(dir, 'r'), a = firstEntry(dir, 'a');
  REQUIRE(!d.empty());
  REQUIRE(!r.empty());
  REQUIRE(!a.empty());
  // fakenect parses names with "%c-%lf-%u-%*s" and skips one header line.
  char kind = 0;
  double sec = 0;
  unsigned ts = 0;
  CHECK(std::sscanf(d.c_str(), "%c-%lf-%u", &kind, &sec, &ts) == 3);
  CHECK(sec >= 1.0);  // fakenect treats a recorded time of 0 as "no previous frame"
  const std::string depth = cuetrack::test::readText(dir + "/" + d);
  CHECK(depth.size() == 17 + 640 * 480 * 2);
  CHECK(depth.compare(0, 17, "P5 640 480 65535\n") == 0);
  int maxRaw = 0;
  for (int i = 0; i < 640 * 480; ++i) {
    const int raw =
        static_cast<uint8_t>(depth[17 + 2 * i]) | (static_cast<uint8_t>(depth[18 + 2 * i]) << 8);
    maxRaw = std::max(maxRaw, raw);
  }
  CHECK(maxRaw == 2047);  // holes are libfreenect's "no reading"
  CHECK(cuetrack::test::readText(dir + "/" + r).compare(0, 14, "P6 640 480 255") == 0);
  CHECK(cuetrack::test::readText(dir + "/" + a).size() == 12);  // sizeof(freenect_raw_tilt_state)
  CHECK(cuetrack::test::readText(dir + "/groundtruth.txt").compare(0, 8, "moving\r\n") == 0);
}

TEST_CASE("fakenect pairing: colour takes the last depth before it, else the next", "[fakenect]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 3);
  std::string index = cuetrack::test::readText(dir + "/INDEX.txt");
  // Reorder: first colour entry before the first depth entry; drop the third depth.
  std::vector<std::string> lines, ds, rs;
  size_t pos = 0;
  while (pos < index.size()) {
    const size_t nl = index.find('\n', pos);
    lines.push_back(index.substr(pos, nl - pos));
    pos = nl + 1;
  }
  for (auto& l : lines) (l[0] == 'd' ? ds : rs).push_back(l);
  REQUIRE(ds.size() == 3);
  std::string out;
  out += rs[0] + "\n" + rs[1] + "\n" + ds[0] + "\n" + rs[2] + "\n" + rs[3] + "\n";
  // rs holds a- and r- entries: rs = a0 r0 a1 r1 a2 r2 -> here: a0 r0 d0 a1 r1
  cuetrack::test::writeText(dir + "/INDEX.txt", out);
  cuetrack::test::writeText(dir + "/groundtruth.txt", "hdr\n0 0.1 0.1 0.1 0.1\n");
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 2);
  auto f = std::make_unique<FrameSlot>();
  REQUIRE(reader.next(*f) == ReadStatus::Ok);
  CHECK(f->hasDepth);  // r0 came before any depth: it takes d0
  CHECK(f->hasGroundTruth);
  REQUIRE(reader.next(*f) == ReadStatus::Ok);
  CHECK(f->hasDepth);              // r1 takes d0 again
  CHECK_FALSE(f->hasGroundTruth);  // BoBoT: the last frame may lack a box
  CHECK(reader.next(*f) == ReadStatus::End);
}

TEST_CASE("fakenect bad input: one line naming the file, or skipped and counted",
          "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 4);
  auto f = std::make_unique<FrameSlot>();
  const std::string d = firstEntry(dir, 'd');
  const std::string r = firstEntry(dir, 'r');

  SECTION("missing INDEX.txt") {
    FakenectReader reader;
    CHECK_FALSE(reader.open((tmp / "nothing").c_str()));
    CHECK(std::string(reader.error()).find("nothing/INDEX.txt") != std::string::npos);
  }
  SECTION("malformed INDEX line names INDEX.txt:line") {
    std::string index = cuetrack::test::readText(dir + "/INDEX.txt");
    cuetrack::test::writeText(dir + "/INDEX.txt", index + "x-garbage\n");
    FakenectReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    const std::string e = reader.error();
    CHECK(e.find("INDEX.txt:13:") != std::string::npos);
    CHECK(e.find('\n') == std::string::npos);
  }
  SECTION("INDEX names a missing depth file") {
    std::remove((dir + "/" + d).c_str());
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()).find(d) != std::string::npos);
    SourceOptions skip;
    skip.skipBadFrames = true;
    FakenectReader skipping;
    REQUIRE(skipping.open(dir.c_str(), skip));
    int n = 0;
    while (skipping.next(*f) == ReadStatus::Ok) ++n;
    CHECK(n == 3);
    CHECK(skipping.skippedFrames() == 1);
  }
  SECTION("INDEX names a missing colour file") {
    std::remove((dir + "/" + r).c_str());
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()).find(r) != std::string::npos);
  }
  SECTION("truncated depth image") {
    const std::string p = dir + "/" + d;
    cuetrack::test::writeText(p, cuetrack::test::readText(p).substr(0, 1000));
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    const std::string e = reader.error();
    CHECK(e.find(d) != std::string::npos);
    CHECK(e.find("truncated") != std::string::npos);
  }
  SECTION("corrupt colour header") {
    const std::string p = dir + "/" + r;
    std::string bytes = cuetrack::test::readText(p);
    bytes[1] = 'X';
    cuetrack::test::writeText(p, bytes);
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()).find(r) != std::string::npos);
  }
  SECTION("unparsable ground-truth line names file:line") {
    cuetrack::test::writeText(dir + "/groundtruth.txt",
                              "hdr\r\n0 0.1 0.1 0.2 0.2\r\n1 0.1 zz 0.2 0.2\r\n");
    FakenectReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("groundtruth.txt:3:") != std::string::npos);
  }
  SECTION("ground-truth count mismatch") {
    cuetrack::test::writeText(dir + "/groundtruth.txt", "hdr\n0 0.1 0.1 0.2 0.2\n");
    FakenectReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("1 ground-truth boxes for 4 frames") !=
          std::string::npos);
  }
  SECTION("maxFrames stops early") {
    SourceOptions opt;
    opt.maxFrames = 2;
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str(), opt));
    int n = 0;
    while (reader.next(*f) == ReadStatus::Ok) ++n;
    CHECK(n == 2);
  }
}

TEST_CASE("fakenect reading allocates nothing per frame after the first", "[fakenect][alloc]") {
  {
    test::AllocScope control;
    auto p = std::make_unique<int>(3);
    REQUIRE(control.allocations() >= 1);
  }
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "twin-crossing", 5);
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));
  auto f = std::make_unique<FrameSlot>();
  REQUIRE(reader.next(*f) == ReadStatus::Ok);
  test::AllocScope scope;
  int n = 1;
  while (reader.next(*f) == ReadStatus::Ok) ++n;
  CHECK(n == 5);
  CHECK(scope.allocations() == 0);
}

TEST_CASE("fakenect writing allocates nothing per frame after the first", "[fakenect][alloc]") {
  TempDir tmp;
  SceneSpec spec;
  REQUIRE(makeScene("moving", &spec));
  spec.frameCount = 4;
  auto src = std::make_unique<SyntheticSource>(spec, 3);
  auto slot = std::make_unique<FrameSlot>();
  FakenectWriter w;
  if (!w.open((tmp / "rec").c_str(), "moving")) FAIL(w.error());
  REQUIRE(src->next(*slot) == ReadStatus::Ok);
  if (!w.write(*slot)) FAIL(w.error());
  test::AllocScope scope;
  while (src->next(*slot) == ReadStatus::Ok)
    if (!w.write(*slot)) FAIL(w.error());
  CHECK(scope.allocations() == 0);
  if (!w.close()) FAIL(w.error());
  CHECK(w.framesWritten() == 4);
}
