// fakenect recordings: synthetic -> writer -> reader round trip, libfreenect's exact
// file layout, pairing, bad input (one line naming the file) and no allocation per frame.
#include <catch2/catch.hpp>

#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "AllocCounter.hpp"
#include "TempDir.hpp"
#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/GroundTruthOut.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;
using cuetrack::test::TempDir;

namespace {

// Writes `frames` frames of a scene as a fakenect recording (640x480 unless told).
void writeScene(const std::string& dir, const char* scene, int frames, uint64_t seed = 3,
                int width = 640, int height = 480) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  spec.frameCount = frames;
  spec.width = width;
  spec.height = height;
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

namespace {
// INDEX entries of one kind ('r', 'd', 'a'), in order.
std::vector<std::string> entries(const std::string& dir, char kind) {
  const std::string index = cuetrack::test::readText(dir + "/INDEX.txt");
  std::vector<std::string> out;
  size_t pos = 0;
  while (pos < index.size()) {
    const size_t nl = index.find('\n', pos);
    const std::string line = index.substr(pos, nl - pos);
    if (!line.empty() && line[0] == kind) out.push_back(line);
    pos = nl == std::string::npos ? index.size() : nl + 1;
  }
  return out;
}
}  // namespace

TEST_CASE("fakenect: a frame of another size than the first is refused", "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 3);
  // A 320x240 recording whose first colour and depth files replace frame 1's.
  writeScene(tmp / "small", "moving", 1, 3, 320, 240);
  const std::string r1 = entries(dir, 'r').at(1), d1 = entries(dir, 'd').at(1);
  test::writeText(dir + "/" + r1, test::readText(tmp / "small/" + entries(tmp / "small", 'r')[0]));
  test::writeText(dir + "/" + d1, test::readText(tmp / "small/" + entries(tmp / "small", 'd')[0]));
  auto f = std::make_unique<FrameSlot>();
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));
  REQUIRE(reader.next(*f) == ReadStatus::Ok);
  CHECK(reader.next(*f) == ReadStatus::Error);
  CHECK(std::string(reader.error()) == dir + "/" + r1 + ": 320x240, the sequence is 640x480");
  SourceOptions skip;
  skip.skipBadFrames = true;
  FakenectReader skipping;
  REQUIRE(skipping.open(dir.c_str(), skip));
  int n = 0;
  while (skipping.next(*f) == ReadStatus::Ok) {
    CHECK(f->rgb.width() == 640);
    ++n;
  }
  CHECK(n == 2);
  CHECK(skipping.skippedFrames() == 1);
}

TEST_CASE("fakenect: a FIFO in place of a frame file is refused, not waited on",
          "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 2);
  const std::string r0 = entries(dir, 'r').at(0);
  REQUIRE(std::remove((dir + "/" + r0).c_str()) == 0);
  REQUIRE(::mkfifo((dir + "/" + r0).c_str(), 0644) == 0);
  auto f = std::make_unique<FrameSlot>();
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.next(*f) == ReadStatus::Error);  // used to block in open() forever
  CHECK(std::string(reader.error()) == dir + "/" + r0 + ": not a regular file");
}

TEST_CASE("fakenect INDEX times: out of range or going back name the line", "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 3);
  const std::string index = test::readText(dir + "/INDEX.txt");
  SECTION("1e300 seconds") {
    const std::string r2 = entries(dir, 'r').at(2);
    std::string bad = index;
    const std::string huge = "r-1e300-" + r2.substr(r2.find('-', 2) + 1);
    bad.replace(bad.find(r2), r2.size(), huge);
    test::writeText(dir + "/INDEX.txt", bad);
    FakenectReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("INDEX.txt:9: INDEX entry 'r-1e300-") !=
          std::string::npos);
    CHECK(std::string(reader.error()).find("seconds 1e+300 outside 0..10000000000") !=
          std::string::npos);
  }
  SECTION("reversed INDEX") {
    std::vector<std::string> lines;
    size_t pos = 0;
    while (pos < index.size()) {
      const size_t nl = index.find('\n', pos);
      lines.push_back(index.substr(pos, nl - pos));
      pos = nl + 1;
    }
    std::string reversed;
    for (auto it = lines.rbegin(); it != lines.rend(); ++it) reversed += *it + "\n";
    test::writeText(dir + "/INDEX.txt", reversed);
    FakenectReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()) ==
          dir +
              "/INDEX.txt:4: time 1.033333 s goes back from 1.066667 s on line 3 (entries must be "
              "in capture order)");
  }
  SECTION("in order: times from the first entry, frame rate from the colour entries") {
    FakenectReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.nominalFps() == Approx(30.0).margin(1e-3));
    auto f = std::make_unique<FrameSlot>();
    for (uint64_t want : {0u, 33333u, 66667u}) {
      REQUIRE(reader.next(*f) == ReadStatus::Ok);
      CHECK(f->timeUs == want);
    }
  }
}

TEST_CASE("fakenect writer refuses a folder that holds a recording", "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 3);
  FakenectWriter w;
  CHECK_FALSE(w.open(dir.c_str()));
  CHECK(std::string(w.error()) ==
        dir + ": already holds a recording (INDEX.txt); write to a new or empty folder");
  FakenectReader reader;  // untouched
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 3);
  REQUIRE(::mkdir((tmp / "empty").c_str(), 0755) == 0);
  CHECK(w.open((tmp / "empty").c_str()));  // an existing empty folder is fine
  CHECK(w.close());
}

TEST_CASE("a groundtruth.txt that is not a file is named, not taken for no ground truth",
          "[fakenect][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 2);
  FakenectReader reader;
  REQUIRE(reader.open(dir.c_str()));  // control
  std::remove((dir + "/groundtruth.txt").c_str());
  REQUIRE(::mkdir((dir + "/groundtruth.txt").c_str(), 0755) == 0);
  CHECK_FALSE(reader.open(dir.c_str()));
  CHECK(std::string(reader.error()) == dir + "/groundtruth.txt: not a regular file");
  REQUIRE(::rmdir((dir + "/groundtruth.txt").c_str()) == 0);
  REQUIRE(reader.open(dir.c_str()));  // a missing one is no ground truth
}

TEST_CASE("what libfreenect's fakenect cannot replay is named before it exits or overruns",
          "[fakenect][bad]") {
  TempDir tmp;
  char err[512];
  const std::string dir = tmp / "rec";
  writeScene(dir, "moving", 3);
  REQUIRE(checkFakenectReplayable(dir.c_str(), err, sizeof err));  // control

  // A missing frame file, an INDEX line it cannot parse, a truncated frame.
  const std::string r1 = entries(dir, 'r').at(1);
  std::remove((dir + "/" + r1).c_str());
  CHECK_FALSE(checkFakenectReplayable(dir.c_str(), err, sizeof err));
  CHECK(std::string(err).find(r1 + " is missing or not a regular file") != std::string::npos);
  writeScene(tmp / "garbage", "moving", 2);
  test::writeText(tmp / "garbage/INDEX.txt",
                  test::readText(tmp / "garbage/INDEX.txt") + "x-garbage\n");
  CHECK_FALSE(checkFakenectReplayable((tmp / "garbage").c_str(), err, sizeof err));
  CHECK(std::string(err).find("INDEX.txt:") != std::string::npos);
  writeScene(tmp / "cut", "moving", 2);
  const std::string d0 = entries(tmp / "cut", 'd').at(0);
  test::writeText(tmp / "cut/" + d0, test::readText(tmp / "cut/" + d0).substr(0, 1000));
  CHECK_FALSE(checkFakenectReplayable((tmp / "cut").c_str(), err, sizeof err));
  CHECK(std::string(err).find(d0 + ": truncated") != std::string::npos);

  // Another size: our reader takes it, fakenect's fixed 640x480 buffers would not.
  writeScene(tmp / "small", "moving", 2, 3, 320, 240);
  CHECK_FALSE(checkFakenectReplayable((tmp / "small").c_str(), err, sizeof err));
  CHECK(std::string(err).find("fakenect replays only 640x480") != std::string::npos);
  CHECK(std::string(err).find('\n') == std::string::npos);
}

TEST_CASE("a writer's ground truth starts at frame 0, and a failed write is said at close") {
  TempDir tmp;
  static FrameSlot frame;  // ~1.5 MiB
  frame.rgb.resize(64, 48);
  frame.hasGroundTruth = true;
  frame.groundTruth = Box{8, 6, 16, 12};
  char err[256] = "";
  GroundTruthOut late;
  late.start(tmp.path(), "late");
  frame.hasGroundTruth = false;
  REQUIRE(late.write(frame, 0, err, sizeof err));  // no truth: nothing made
  REQUIRE_FALSE(rec::exists((tmp / "groundtruth.txt").c_str()));
  frame.hasGroundTruth = true;
  REQUIRE_FALSE(late.write(frame, 1, err, sizeof err));
  CHECK(std::string(err) == tmp.path() + ": ground truth starts at frame 1, not 0");
  REQUIRE(late.close(err, sizeof err));  // nothing was open

  GroundTruthOut full;  // groundtruth.txt is /dev/full: the data is lost at close
  REQUIRE(::symlink("/dev/full", (tmp / "groundtruth.txt").c_str()) == 0);
  full.start(tmp.path(), "full");
  REQUIRE(full.write(frame, 0, err, sizeof err));
  REQUIRE_FALSE(full.close(err, sizeof err));
  CHECK(std::string(err) ==
        tmp.path() + "/groundtruth.txt: write failed (No space left on device)");
}
