// OpenCV-backed formats: RGB-D folder and OTB round trips from synthetic scenes, BoBoT
// video (self-made and the real benchmark files), TUM stills, and bad input.
#include <catch2/catch.hpp>

#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <csignal>
#include <cstring>
#include <memory>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>
#include <opencv2/videoio.hpp>
#include <set>
#include <string>

#include "SharedData.hpp"
#include "Skip.hpp"
#include "TempDir.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/OpenCvSources.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;
using cuetrack::test::TempDir;

namespace {

std::unique_ptr<SyntheticSource> synth(const char* scene, int frames) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  spec.frameCount = frames;
  return std::make_unique<SyntheticSource>(spec, 11);
}

void writeRgbd(const std::string& dir, const char* scene, int frames) {
  auto src = synth(scene, frames);
  auto slot = std::make_unique<FrameSlot>();
  RgbdFolderWriter w;
  if (!(w.open(dir.c_str(), scene))) FAIL(w.error());
  while (src->next(*slot) == ReadStatus::Ok)
    if (!(w.write(*slot))) FAIL(w.error());
  if (!(w.close())) FAIL(w.error());
}

void checkBox(const Box& a, const Box& b, float tol) {
  CHECK(a.empty() == b.empty());
  CHECK(a.x == Approx(b.x).margin(tol));
  CHECK(a.y == Approx(b.y).margin(tol));
  CHECK(a.w == Approx(b.w).margin(tol));
  CHECK(a.h == Approx(b.h).margin(tol));
}

}  // namespace

TEST_CASE("synthetic -> RGB-D folder -> reader is lossless", "[opencv][rgbd]") {
  TempDir tmp;
  const std::string dir = tmp / "seq";
  writeRgbd(dir, "twin-crossing", 5);
  CHECK(test::pathExists(dir + "/rgb/000004.png"));
  CHECK(test::pathExists(dir + "/depth/000004.png"));
  CHECK(test::readText(dir + "/groundtruth.txt").rfind("twin-crossing\r\n0 ", 0) == 0);

  RgbdFolderReader reader;
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 5);
  CHECK(std::string(reader.name()) == "seq");
  auto src = synth("twin-crossing", 5);
  auto want = std::make_unique<FrameSlot>(), got = std::make_unique<FrameSlot>();
  int n = 0;
  while (reader.next(*got) == ReadStatus::Ok) {
    REQUIRE(src->next(*want) == ReadStatus::Ok);
    CHECK(got->index == n);
    CHECK(std::memcmp(got->rgb.data(), want->rgb.data(), 640 * 480 * 3) == 0);
    REQUIRE(got->hasDepth);
    CHECK(std::memcmp(got->depthMm.data(), want->depthMm.data(), 640 * 480 * 2) == 0);
    CHECK(got->hasGroundTruth);
    checkBox(got->groundTruth, want->groundTruth, 1e-3f);
    CHECK(got->intrinsics.fx == Approx(want->intrinsics.fx).margin(1e-3));
    CHECK(got->intrinsics.cy == Approx(want->intrinsics.cy).margin(1e-3));
    CHECK(got->timeUs == want->timeUs);
    ++n;
  }
  CHECK(n == 5);
}

TEST_CASE("RGB-D folder bad input", "[opencv][rgbd][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "seq";
  writeRgbd(dir, "moving", 3);
  auto f = std::make_unique<FrameSlot>();

  SECTION("truncated colour PNG names the file; skipping counts it") {
    const std::string p = dir + "/rgb/000001.png";
    test::writeText(p, test::readText(p).substr(0, 200));
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK(reader.next(*f) == ReadStatus::Error);
    const std::string e = reader.error();
    CHECK(e.find("rgb/000001.png") != std::string::npos);
    CHECK(e.find('\n') == std::string::npos);
    SourceOptions skip;
    skip.skipBadFrames = true;
    RgbdFolderReader skipping;
    REQUIRE(skipping.open(dir.c_str(), skip));
    int n = 0;
    while (skipping.next(*f) == ReadStatus::Ok) ++n;
    CHECK(n == 2);
    CHECK(skipping.skippedFrames() == 1);
  }
  SECTION("corrupt depth (8-bit) names the file") {
    cv::imwrite(dir + "/depth/000000.png", cv::Mat(480, 640, CV_8UC1, cv::Scalar(9)));
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error())
              .find("depth/000000.png: depth must be 16-bit single-channel, not 8-bit with 1") !=
          std::string::npos);
  }
  SECTION("16-bit colour PNG as depth is refused, not read as grey") {
    cv::imwrite(dir + "/depth/000001.png", cv::Mat(480, 640, CV_16UC3, cv::Scalar(900, 900, 900)));
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error())
              .find("depth/000001.png: depth must be 16-bit single-channel, not 16-bit with 3 "
                    "channels") != std::string::npos);
  }
  SECTION("16-bit colour PNG as colour is refused, not scaled to 8 bits") {
    cv::imwrite(dir + "/rgb/000002.png", cv::Mat(480, 640, CV_16UC3, cv::Scalar(900, 900, 900)));
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error())
              .find("rgb/000002.png: colour must be 8 bits per channel, not 16-bit") !=
          std::string::npos);
  }
  SECTION("missing depth file") {
    std::remove((dir + "/depth/000002.png").c_str());
    RgbdFolderReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("depth: 2 depth images for 3 colour images") !=
          std::string::npos);
  }
  SECTION("ground-truth count mismatch") {
    test::writeText(dir + "/groundtruth.txt", "seq\n0 0.1 0.1 0.1 0.1\n");
    RgbdFolderReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("groundtruth.txt: 1 ground-truth boxes for 3 frames") !=
          std::string::npos);
  }
  SECTION("unparsable intrinsics") {
    test::writeText(dir + "/intrinsics.txt", "518 x 3 4\n");
    RgbdFolderReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()).find("intrinsics.txt:") != std::string::npos);
  }
  SECTION("ground truth override path") {
    test::writeText(tmp / "other.txt", "hdr\n0 0.5 0.5 0.25 0.25\n1 0 0 0 0\n2 0 0 0 0\n");
    SourceOptions opt;
    const std::string other = tmp / "other.txt";
    opt.gtPath = other.c_str();
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str(), opt));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    checkBox(f->groundTruth, Box{320, 240, 160, 120}, 1e-3f);
  }
}

TEST_CASE("OTB folder: JPEG frames and 1-based boxes", "[opencv][otb]") {
  TempDir tmp;
  const std::string dir = tmp / "Otb";
  char err[256] = "";
  REQUIRE(rec::makeDirectories((dir + "/img").c_str(), err, sizeof err));
  auto src = synth("box", 4);
  auto slot = std::make_unique<FrameSlot>();
  GtWriter gt;
  REQUIRE(
      gt.open((dir + "/groundtruth_rect.txt").c_str(), GtFormat::Otb, nullptr, err, sizeof err));
  std::vector<Box> boxes;
  std::vector<std::vector<uint8_t>> pixels;
  for (int i = 0; i < 4; ++i) {
    REQUIRE(src->next(*slot) == ReadStatus::Ok);
    cv::Mat rgb(480, 640, CV_8UC3, slot->rgb.data()), bgr;
    cv::cvtColor(rgb, bgr, cv::COLOR_RGB2BGR);
    char name[64];
    std::snprintf(name, sizeof name, "/img/%04d.jpg", i + 1);
    REQUIRE(cv::imwrite(dir + name, bgr, {cv::IMWRITE_JPEG_QUALITY, 95}));
    gt.write(slot->groundTruth, 640, 480);
    boxes.push_back(slot->groundTruth);
    const uint8_t* p = reinterpret_cast<const uint8_t*>(slot->rgb.data());
    pixels.emplace_back(p, p + 640 * 480 * 3);
  }
  REQUIRE(gt.close());
  OtbFolderReader reader;
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 4);
  auto f = std::make_unique<FrameSlot>();
  for (int i = 0; i < 4; ++i) {
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK_FALSE(f->hasDepth);
    checkBox(f->groundTruth, boxes[static_cast<size_t>(i)], 1e-3f);
    double diff = 0;
    const uint8_t* p = reinterpret_cast<const uint8_t*>(f->rgb.data());
    for (size_t k = 0; k < pixels[0].size(); ++k)
      diff += std::abs(p[k] - pixels[static_cast<size_t>(i)][k]);
    CHECK(diff / pixels[0].size() < 4.0);  // JPEG at quality 95
  }
  CHECK(reader.next(*f) == ReadStatus::End);
  // Comma-free, tab-separated boxes read the same.
  test::writeText(dir + "/groundtruth_rect.txt", "1\t1\t10\t10\n1 1 10 10\n1 1 10 10\n1 1 10 10\n");
  OtbFolderReader tabs;
  REQUIRE(tabs.open(dir.c_str()));
  REQUIRE(tabs.next(*f) == ReadStatus::Ok);
  checkBox(f->groundTruth, Box{0, 0, 10, 10}, 1e-4f);
}

TEST_CASE("OTB folder: a truncated JPEG is named, or skipped and counted", "[opencv][otb][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "Otb";
  {
    auto src = synth("box", 3);
    auto slot = std::make_unique<FrameSlot>();
    OtbFolderWriter w;
    if (!w.open(dir.c_str())) FAIL(w.error());
    while (src->next(*slot) == ReadStatus::Ok)
      if (!w.write(*slot)) FAIL(w.error());
    if (!w.close()) FAIL(w.error());
  }
  // Cut frame 2 to two thirds: libjpeg would decode it with grey rows and a warning.
  const std::string p = dir + "/img/0002.jpg";
  const std::string bytes = test::readText(p);
  test::writeText(p, bytes.substr(0, bytes.size() * 2 / 3));
  REQUIRE_FALSE(cv::imread(p).empty());  // what OpenCV alone would accept
  auto f = std::make_unique<FrameSlot>();
  OtbFolderReader r;
  REQUIRE(r.open(dir.c_str()));
  REQUIRE(r.next(*f) == ReadStatus::Ok);
  CHECK(r.next(*f) == ReadStatus::Error);
  CHECK(std::string(r.error()) == p + ": truncated JPEG (no end-of-image marker)");
  SourceOptions skip;
  skip.skipBadFrames = true;
  OtbFolderReader s;
  REQUIRE(s.open(dir.c_str(), skip));
  int n = 0;
  while (s.next(*f) == ReadStatus::Ok) ++n;
  CHECK(n == 2);
  CHECK(s.skippedFrames() == 1);
}
TEST_CASE("BoBoT video reader: own video, unreadable video", "[opencv][bobot]") {
  TempDir tmp;
  const std::string avi = tmp / "Vid_T_test.avi";
  {
    cv::VideoWriter vw(avi, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0, cv::Size(320, 240));
    if (!vw.isOpened()) {
      CUETRACK_SKIP("this OpenCV cannot write MJPG AVI");
    }
    for (int i = 0; i < 6; ++i) vw.write(cv::Mat(240, 320, CV_8UC3, cv::Scalar(i * 40, 0, 0)));
  }
  test::writeText(tmp / "Vid_T_test.gt.txt",
                  "./Vid_T_test.avi\r\n0 0.5 0.5 0.25 0.25\r\n1 0 0 0 0\r\n2 0.1 0.1 0.1 0.1\r\n"
                  "3 0.1 0.1 0.1 0.1\r\n4 0.1 0.1 0.1 0.1\r\n");
  BobotVideoReader reader;
  REQUIRE(reader.open(avi.c_str()));
  CHECK(reader.frameCount() == 6);
  CHECK(reader.groundTruth().header() == "./Vid_T_test.avi");
  auto f = std::make_unique<FrameSlot>();
  int n = 0;
  while (reader.next(*f) == ReadStatus::Ok) {
    CHECK(f->rgb.width() == 320);
    CHECK(f->hasGroundTruth == (n < 5));
    CHECK(f->timeUs == static_cast<uint64_t>(n * 40000));
    if (n == 0) checkBox(f->groundTruth, Box{160, 120, 80, 60}, 1e-3f);
    if (n == 1) CHECK(f->groundTruth.empty());
    ++n;
  }
  CHECK(n == 6);

  SECTION("garbage video") {
    const std::string bad = tmp / "bad.avi";
    test::writeText(bad, std::string(5000, 'x'));
    BobotVideoReader r;
    CHECK_FALSE(r.open(bad.c_str()));
    CHECK(std::string(r.error()).find("bad.avi: cannot open video: no stream to decode (the file "
                                      "is cut short, damaged or holds no video track") !=
          std::string::npos);
  }
  SECTION("empty video") {
    const std::string empty = tmp / "empty.mp4";
    test::writeText(empty, "");
    BobotVideoReader r;
    CHECK_FALSE(r.open(empty.c_str()));
    CHECK(std::string(r.error()) == empty + ": empty file (0 bytes): no video to read");
  }
  SECTION("missing video") {
    BobotVideoReader r;
    CHECK_FALSE(r.open((tmp / "none.avi").c_str()));
    CHECK(std::string(r.error()).find("none.avi: no such video file") != std::string::npos);
  }
  SECTION("GT count mismatch") {
    test::writeText(tmp / "Vid_T_test.gt.txt", "h\r\n0 0.5 0.5 0.25 0.25\r\n");
    BobotVideoReader r;
    CHECK_FALSE(r.open(avi.c_str()));
    CHECK(std::string(r.error()).find("1 ground-truth boxes for 6 video frames") !=
          std::string::npos);
  }
}

TEST_CASE("BoBoT video: a damaged frame is an error naming it, or skipped and counted",
          "[opencv][bobot][bad]") {
  TempDir tmp;
  const std::string avi = tmp / "Vid_D_damaged.avi";
  {
    auto src = synth("moving", 8);
    auto slot = std::make_unique<FrameSlot>();
    BobotVideoWriter w;
    if (!w.open(avi.c_str(), 30.0)) FAIL(w.error());
    while (src->next(*slot) == ReadStatus::Ok)
      if (!w.write(*slot)) FAIL(w.error());
    if (!w.close()) FAIL(w.error());
  }
  auto f = std::make_unique<FrameSlot>();
  {  // intact: every frame reads, none counted as damaged
    BobotVideoReader r;
    REQUIRE(r.open(avi.c_str()));
    int n = 0;
    while (r.next(*f) == ReadStatus::Ok) ++n;
    CHECK(n == 8);
    CHECK(r.skippedFrames() == 0);
  }
  test::damageAviFrame(avi, 5);
  BobotVideoReader r;
  REQUIRE(r.open(avi.c_str()));
  int n = 0;
  ReadStatus st;
  while ((st = r.next(*f)) == ReadStatus::Ok) ++n;
  CHECK(st == ReadStatus::Error);
  CHECK(n == 5);
  const std::string e = r.error();
  CHECK(e.find("Vid_D_damaged.avi: frame 5 is damaged") != std::string::npos);
  CHECK(e.find('\n') == std::string::npos);

  SourceOptions skip;
  skip.skipBadFrames = true;
  BobotVideoReader s;
  REQUIRE(s.open(avi.c_str(), skip));
  std::vector<int> indices;
  while (s.next(*f) == ReadStatus::Ok) indices.push_back(f->index);
  CHECK(indices == std::vector<int>{0, 1, 2, 3, 4, 6, 7});
  CHECK(s.skippedFrames() == 1);
}

TEST_CASE("real BoBoT sequences: frame counts and ground-truth alignment", "[opencv][shared]") {
  const std::string dir = test::sharedDataDir() + "/bobot";
  if (!test::pathExists(dir)) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  struct Seq {
    const char* name;
    int frames;
  };
  auto f = std::make_unique<FrameSlot>();
  for (Seq s : {Seq{"Vid_C_juice", 405}, Seq{"Vid_E_person_partially_occluded", 306},
                Seq{"Vid_H_panda", 413}}) {
    INFO(s.name);
    const std::string avi = dir + "/" + s.name + ".avi";
    BobotVideoReader reader;
    REQUIRE(reader.open(avi.c_str()));
    CHECK(reader.groundTruth().count() == s.frames - 1);
    CHECK(reader.groundTruth().header() == std::string("./") + s.name + ".avi");
    int n = 0, withGt = 0, visible = 0;
    while (reader.next(*f) == ReadStatus::Ok) {
      REQUIRE(f->rgb.width() == 320);
      REQUIRE(f->rgb.height() == 240);
      CHECK(f->index == n);
      // Frame N <-> GT index N; only the last frame has none.
      CHECK(f->hasGroundTruth == (n < s.frames - 1));
      withGt += f->hasGroundTruth;
      if (!f->groundTruth.empty()) {
        ++visible;
        CHECK(f->groundTruth.x >= -1.f);
        CHECK(f->groundTruth.x + f->groundTruth.w <= 321.f);
        CHECK(f->groundTruth.y + f->groundTruth.h <= 241.f);
      }
      ++n;
    }
    CHECK(std::string(reader.error()).empty());
    CHECK(n == s.frames);
    CHECK(withGt == s.frames - 1);
    CHECK(visible > s.frames / 2);
  }
  // Alignment against the file itself: juice frame 0 is GT line 2 of the file.
  BobotVideoReader juice;
  REQUIRE(juice.open((dir + "/Vid_C_juice.avi").c_str()));
  REQUIRE(juice.next(*f) == ReadStatus::Ok);
  checkBox(f->groundTruth, Box{0.410029f * 320, 0.208388f * 240, 0.114061f * 320, 0.373526f * 240},
           1e-3f);
}

TEST_CASE("real TUM stills: 16-bit PNG depth (value / 5 = mm)", "[opencv][shared][stills]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/tum-fr1";
  if (!test::pathExists(dir)) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  auto depth = std::make_unique<FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>>();
  auto colour = std::make_unique<FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight>>();
  char err[256] = "";
  for (int i = 1; i <= 2; ++i) {
    const std::string d = dir + "/" + std::to_string(i) + "_depth.png";
    const std::string c = dir + "/" + std::to_string(i) + ".png";
    INFO(d);
    REQUIRE(loadDepthPng16(d.c_str(), *depth, err, sizeof err));
    REQUIRE(loadColourImage(c.c_str(), *colour, err, sizeof err));
    CHECK(depth->width() == 640);
    CHECK(depth->height() == 480);
    CHECK(colour->width() == depth->width());
    std::vector<int> mm;
    for (int k = 0; k < 640 * 480; ++k)
      if (depth->data()[k]) mm.push_back(depth->data()[k] / 5);
    REQUIRE(mm.size() > 640 * 480 / 2);
    std::sort(mm.begin(), mm.end());
    CHECK(mm.front() >= 400);
    CHECK(mm.back() <= 12000);  // TUM keeps readings a little past 10 m
    CHECK(mm[mm.size() / 2] > 500);
    CHECK(mm[mm.size() / 2] < 6000);
  }
  CHECK_FALSE(loadDepthPng16((dir + "/1.png").c_str(), *depth, err, sizeof err));  // 8-bit colour
  CHECK(std::string(err).find("1.png: depth must be 16-bit single-channel, not 8-bit with 3") !=
        std::string::npos);
}

TEST_CASE("OTB and BoBoT-video writers round-trip the ground truth", "[opencv][otb][bobot]") {
  TempDir tmp;
  auto slot = std::make_unique<FrameSlot>();
  std::vector<Box> truth;
  {
    auto src = synth("occlusion", 5);
    OtbFolderWriter otb;
    BobotVideoWriter avi;
    if (!otb.open((tmp / "otb").c_str())) FAIL(otb.error());
    if (!avi.open((tmp / "Vid_S_synth.avi").c_str(), 30.0)) FAIL(avi.error());
    while (src->next(*slot) == ReadStatus::Ok) {
      if (!otb.write(*slot)) FAIL(otb.error());
      if (!avi.write(*slot)) FAIL(avi.error());
      truth.push_back(slot->groundTruth);
    }
    if (!otb.close()) FAIL(otb.error());
    if (!avi.close()) FAIL(avi.error());
  }
  OtbFolderReader otb;
  REQUIRE(otb.open((tmp / "otb").c_str()));
  BobotVideoReader avi;
  REQUIRE(avi.open((tmp / "Vid_S_synth.avi").c_str()));
  CHECK(avi.groundTruth().header() == "./Vid_S_synth.avi");
  CHECK(avi.frameCount() == 5);
  for (size_t i = 0; i < truth.size(); ++i) {
    REQUIRE(otb.next(*slot) == ReadStatus::Ok);
    checkBox(slot->groundTruth, truth[i], 2e-3f);
    REQUIRE(avi.next(*slot) == ReadStatus::Ok);
    checkBox(slot->groundTruth, truth[i], 1e-3f);
    CHECK(slot->timeUs == static_cast<uint64_t>(std::llround(i * 1e6 / 30.0)));
  }
  CHECK(otb.next(*slot) == ReadStatus::End);
  CHECK(avi.next(*slot) == ReadStatus::End);
  BobotVideoWriter bad;
  CHECK_FALSE(bad.open((tmp / "x.mp4").c_str()));
  CHECK(std::string(bad.error()).find("x.mp4: the video name must end in .avi") !=
        std::string::npos);
}

namespace {
// A still of 128 x 96: colour and depth that encode their own pixel position.
void writeStill(const TempDir& tmp) {
  cv::Mat bgr(96, 128, CV_8UC3), depth(96, 128, CV_16UC1);
  for (int y = 0; y < 96; ++y)
    for (int x = 0; x < 128; ++x) {
      bgr.at<cv::Vec3b>(y, x) = cv::Vec3b(static_cast<uint8_t>(40 + x),
                                          static_cast<uint8_t>(60 + y), static_cast<uint8_t>(128));
      depth.at<uint16_t>(y, x) = static_cast<uint16_t>(1000 + 10 * x + y);
    }
  REQUIRE(cv::imwrite(tmp / "c.png", bgr));
  REQUIRE(cv::imwrite(tmp / "d.png", depth));
}
}  // namespace

TEST_CASE("panned still: crops, depth, ground truth and intrinsics move together",
          "[opencv][pan]") {
  TempDir tmp;
  writeStill(tmp);
  const std::string spec =
      "pan:" + tmp / "c.png" + "," + tmp / "d.png" + ",40,30,30,20,100,101,64,48:20";
  StillPanReader r;
  REQUIRE(r.open(spec.c_str()));
  CHECK(r.frameCount() == 20);
  // Named by the still's folder, its stem and the box's corner.
  const std::string name = r.name();
  CHECK(name == "pan-" + tmp.path().substr(tmp.path().find_last_of('/') + 1) + "-c-40-30");
  auto slot = std::make_unique<FrameSlot>();
  int frames = 0;
  std::set<int> offsets;
  while (r.next(*slot) == ReadStatus::Ok) {
    INFO("frame " << frames);
    ++frames;
    // The crop is the still less 1/16 per side: 112 x 84; cx, cy move by that margin.
    REQUIRE(slot->rgb.width() == 112);
    REQUIRE(slot->rgb.height() == 84);
    REQUIRE(slot->hasDepth);
    CHECK(slot->intrinsics.fx == 100.f);
    CHECK(slot->intrinsics.cx == 64.f - 8.f);
    CHECK(slot->intrinsics.cy == 48.f - 6.f);
    REQUIRE(slot->hasGroundTruth);
    const Box& g = slot->groundTruth;
    CHECK(g.w == 30.f);
    CHECK(g.h == 20.f);
    // The crop's offset from the box's shift: depth there is the still's.
    const int ox = 40 - static_cast<int>(g.x), oy = 30 - static_cast<int>(g.y);
    CHECK(ox >= 0);
    CHECK(ox <= 16);
    CHECK(oy >= 0);
    CHECK(oy <= 12);
    offsets.insert(ox * 100 + oy);
    for (int y = 0; y < 84; y += 7)
      for (int x = 0; x < 112; x += 5)
        REQUIRE(slot->depthMm.data()[y * 112 + x] == 1000 + 10 * (x + ox) + (y + oy));
    // Colour: the still's plus small noise.
    double diff = 0;
    for (int x = 0; x < 112; ++x)
      diff += std::abs(slot->rgb.data()[10 * 112 + x].b - (40 + x + ox));
    CHECK(diff / 112 < 4.0);
    CHECK(slot->timeUs == static_cast<uint64_t>(std::llround((frames - 1) * 1e6 / 30.0)));
  }
  CHECK(frames == 20);
  CHECK(offsets.size() > 10);  // it moves

  // Depth units: 0.2 mm per unit (TUM) scales every reading.
  StillPanReader tum;
  const std::string tumSpec =
      "pan:" + tmp / "c.png" + "," + tmp / "d.png" + ",40,30,30,20,100,101,64,48,0.2:1";
  REQUIRE(tum.open(tumSpec.c_str()));
  REQUIRE(tum.next(*slot) == ReadStatus::Ok);
  const int ox = 40 - static_cast<int>(slot->groundTruth.x);
  const int oy = 30 - static_cast<int>(slot->groundTruth.y);
  CHECK(slot->depthMm.data()[0] == std::lround(0.2 * (1000 + 10 * ox + oy)));
}

TEST_CASE("panned still: bad specs give one line naming the fault", "[opencv][pan][bad]") {
  TempDir tmp;
  writeStill(tmp);
  const std::string c = tmp / "c.png", d = tmp / "d.png";
  const auto fails = [](const std::string& spec, const std::string& expect) {
    StillPanReader r;
    INFO(spec);
    REQUIRE_FALSE(r.open(spec.c_str()));
    INFO(r.error());
    CHECK(std::string(r.error()).find(expect) != std::string::npos);
    CHECK(std::string(r.error()).find('\n') == std::string::npos);
  };
  fails("pan:" + c + "," + d + ",1,2,3", "expected pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy");
  fails("pan:" + c + "," + d + ",40,30,wide,20,100,101,64,48", "w 'wide' is not a number");
  fails("pan:" + c + "," + d + ",40,30,-3,20,100,101,64,48", "must be positive");
  fails("pan:" + c + "," + d + ",400,300,30,20,100,101,64,48", "lies outside the 128x96 still");
  fails("pan:" + c + "," + d + ",40,30,30,20,100,101,64,48:0", "frame count '0'");
  fails("pan:" + tmp / "nope.png" + "," + d + ",40,30,30,20,100,101,64,48",
        "nope.png: cannot decode image");
  fails("pan:" + c + "," + c + ",40,30,30,20,100,101,64,48",
        "c.png: depth must be 16-bit single-channel");
}

TEST_CASE("scene in a still: the still's size, intrinsics and depth, the scene over it",
          "[opencv][still]") {
  TempDir tmp;
  writeStill(tmp);  // 128x96, depth 1000 + 10 x + y mm
  const std::string spec =
      "still:" + tmp / "c.png" + "," + tmp / "d.png" + ",100,101,64,48:flat-turn@70,40,60:4";
  StillSceneReader r;
  REQUIRE(r.open(spec.c_str()));
  CHECK(r.frameCount() == 4);
  CHECK(r.nominalFps() == 30.0);
  // Named by the still's folder, its stem, the scene and the pixel.
  CHECK(std::string(r.name()) ==
        "still-" + tmp.path().substr(tmp.path().find_last_of('/') + 1) + "-c-flat-turn-70-40");
  auto slot = std::make_unique<FrameSlot>();
  const cv::Mat still = cv::imread(tmp / "c.png", cv::IMREAD_COLOR);
  int frames = 0;
  while (r.next(*slot) == ReadStatus::Ok) {
    INFO("frame " << frames);
    ++frames;
    REQUIRE(slot->rgb.width() == 128);
    REQUIRE(slot->rgb.height() == 96);
    CHECK(slot->intrinsics.fx == 100.f);
    CHECK(slot->intrinsics.fy == 101.f);
    CHECK(slot->intrinsics.cx == 64.f);
    REQUIRE(slot->hasGroundTruth);
    const Box g = slot->groundTruth;
    REQUIRE_FALSE(g.empty());
    CHECK(g.x + g.w / 2 == Approx(70.f).margin(2.f));
    CHECK(g.y + g.h / 2 == Approx(40.f).margin(2.f));
    // The surface near 70,40 is at 1740 mm: the box's front 60 + 50 mm before it.
    const SynthTruth& t = r.scene()->truth();
    CHECK(t.centreMm[2] == Approx(1740.f - 60.f - 25.f).margin(1.f));
    const uint16_t centre = slot->depthMm.data()[40 * 128 + 70];
    CHECK(centre == Approx(1740 - 110).margin(25));
    // Far from the box: the still, depth exact and colour within the noise.
    for (int y = 0; y < 96; y += 5)
      for (int x = 0; x < 128; x += 3) {
        if (x > g.x - 6 && x < g.x + g.w + 2 && y > g.y - 2 && y < g.y + g.h + 2) continue;
        REQUIRE(slot->depthMm.data()[y * 128 + x] == 1000 + 10 * x + y);
        const cv::Vec3b bgr = still.at<cv::Vec3b>(y, x);
        REQUIRE(std::abs(slot->rgb.data()[y * 128 + x].r - bgr[2]) <= 2);
      }
  }
  CHECK(frames == 4);
  // Depth units: 0.2 mm per unit (TUM) scales the still before the scene is placed.
  StillSceneReader tum;
  const std::string tumSpec =
      "still:" + tmp / "c.png" + "," + tmp / "d.png" + ",100,101,64,48,0.2:moving@70,40,0:1";
  CHECK_FALSE(tum.open(tumSpec.c_str()));  // 348 mm: nearer than the Kinect reads
  CHECK(std::string(tum.error()).find("nearer than 500 mm (the surface at 70,40 is 348 mm away)") !=
        std::string::npos);
}

TEST_CASE("scene in a still: bad specs give one line naming the fault", "[opencv][still][bad]") {
  TempDir tmp;
  writeStill(tmp);
  const std::string c = tmp / "c.png", d = tmp / "d.png";
  const std::string still = "still:" + c + "," + d;
  const auto fails = [](const std::string& spec, const std::string& expect) {
    StillSceneReader r;
    INFO(spec);
    REQUIRE_FALSE(r.open(spec.c_str()));
    INFO(r.error());
    CHECK(std::string(r.error()).find(expect) != std::string::npos);
    CHECK(std::string(r.error()).find('\n') == std::string::npos);
    auto slot = std::make_unique<FrameSlot>();
    CHECK(r.next(*slot) == ReadStatus::Error);
  };
  const std::string syntax = "expected still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm";
  fails(still + ",100,101,64,48", syntax + "[:frames] (no :SCENE@u,v,gapMm)");
  fails(still + ",100,101,64,48:moving", "(no :SCENE@u,v,gapMm)");
  fails(still + ",100,101:moving@60,40,50", "(4 still fields, 3 placement fields)");
  fails(still + ",100,101,64,48:moving@60,40", "(6 still fields, 2 placement fields)");
  fails(still + ",100,wide,64,48:moving@60,40,50", "fy 'wide' is not a number");
  fails(still + ",100,101,64,48:moving@60,x,50", "v 'x' is not a number");
  fails(still + ",100,101,64,48,0:moving@60,40,50", "fx, fy and mmPerUnit must be positive");
  fails(still + ",100,101,64,48:moving@60,40,-5", "gapMm must be >= 0");
  fails(still + ",100,101,64,48:nope@60,40,50", "unknown scene 'nope' (scenes: moving,");
  fails(still + ",100,101,64,48:moving@60,40,50:0", "frame count '0' is not a number");
  fails(still + ",100,101,64,48:moving@600,40,50", "pixel 600,40 lies outside the 128x96 still");
  fails("still:" + tmp / "nope.png" + "," + d + ",100,101,64,48:moving@60,40,50",
        "nope.png: cannot decode image");
  fails("still:" + c + "," + c + ",100,101,64,48:moving@60,40,50",
        "c.png: depth must be 16-bit single-channel");
}

TEST_CASE("scene in a still: the real stills of the development set keep the target in view",
          "[opencv][still][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills";
  if (!test::pathExists(dir + "/tum-fr1") || !test::pathExists(dir + "/nyu-joinmap")) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  // The sequences of scripts/devset.sh and scripts/benchmarks.sh.
  const std::string tum = "still:" + dir + "/tum-fr1/1.png," + dir +
                          "/tum-fr1/1_depth.png,517.3,516.5,318.6,255.3,0.2:";
  const auto nyu = [&](int i) {
    const std::string n = std::to_string(i);
    return "still:" + dir + "/nyu-joinmap/color/" + n + ".png," + dir + "/nyu-joinmap/depth/" + n +
           ".pgm,518,519,325.5,253.5:";
  };
  struct Case {
    std::string spec;
    int minInView;       // frames of 150 with a ground-truth box
    float minMeanShown;  // mean visible fraction (hidden by the still, a hand, an occluder)
  };
  const Case cases[] = {
      {tum + "flat-turn@260,170,100", 150, 0.9f},
      {nyu(5) + "occlusion@370,200,60", 120, 0.75f},
      {nyu(3) + "turn@170,320,150", 150, 0.95f},
      {tum + "held@300,180,300", 150, 0.6f},
  };
  auto slot = std::make_unique<FrameSlot>();
  for (const Case& c : cases) {
    INFO(c.spec);
    StillSceneReader r;
    REQUIRE(r.open(c.spec.c_str()));
    int inView = 0;
    double shown = 0, nearSurface = 0;
    while (r.next(*slot) == ReadStatus::Ok) {
      const SynthTruth& t = r.scene()->truth();
      inView += !slot->groundTruth.empty();
      shown += t.visibleFraction();
      // Where the target is seen, its depth is the object's: the box's centre reads within
      // 200 mm of the target's centre (or is its shadow, a hand or an occluder in front).
      const Box& g = slot->groundTruth;
      if (g.empty()) continue;
      const uint16_t d =
          slot->depthMm
              .data()[static_cast<int>(g.y + g.h / 2) * 640 + static_cast<int>(g.x + g.w / 2)];
      nearSurface += d != 0 && std::fabs(d - t.centreMm[2]) < 200.f;
    }
    CHECK(inView >= c.minInView);
    CHECK(shown / 150 >= c.minMeanShown);
    CHECK(nearSurface >= 0.5 * inView);
  }
}

namespace {
// Frame `name` of the RGB-D folder `dir` replaced by a flat 320x240 colour + depth pair.
void writeSmallRgbdFrame(const std::string& dir, const char* name) {
  REQUIRE(
      cv::imwrite(dir + "/rgb/" + name + ".png", cv::Mat(240, 320, CV_8UC3, cv::Scalar(1, 2, 3))));
  REQUIRE(
      cv::imwrite(dir + "/depth/" + name + ".png", cv::Mat(240, 320, CV_16UC1, cv::Scalar(900))));
}
}  // namespace

TEST_CASE("image folders: a frame of another size than the first is refused",
          "[opencv][rgbd][otb][bad]") {
  TempDir tmp;
  auto f = std::make_unique<FrameSlot>();
  SECTION("RGB-D folder") {
    const std::string dir = tmp / "seq";
    writeRgbd(dir, "moving", 3);
    writeSmallRgbdFrame(dir, "000001");
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()) == dir + "/rgb/000001.png: 320x240, the sequence is 640x480");
  }
  SECTION("OTB folder") {
    const std::string dir = tmp / "otb";
    REQUIRE(rec::makeDirectories((dir + "/img").c_str(), nullptr, 0));
    REQUIRE(cv::imwrite(dir + "/img/0001.jpg", cv::Mat(240, 320, CV_8UC3, cv::Scalar(9))));
    REQUIRE(cv::imwrite(dir + "/img/0002.jpg", cv::Mat(120, 160, CV_8UC3, cv::Scalar(9))));
    OtbFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    REQUIRE(reader.next(*f) == ReadStatus::Ok);
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()) == dir + "/img/0002.jpg: 160x120, the sequence is 320x240");
  }
}

TEST_CASE("RGB-D folder: a FIFO in place of an image is refused, not waited on",
          "[opencv][rgbd][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "seq";
  writeRgbd(dir, "moving", 2);
  auto f = std::make_unique<FrameSlot>();
  for (const char* sub : {"/rgb/000000.png", "/depth/000000.png"}) {
    INFO(sub);
    const std::string p = dir + sub;
    const std::string keep = test::readText(p);
    REQUIRE(std::remove(p.c_str()) == 0);
    REQUIRE(::mkfifo(p.c_str(), 0644) == 0);
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()) == p + ": not a regular file");
    REQUIRE(std::remove(p.c_str()) == 0);
    test::writeText(p, keep);
  }
}

TEST_CASE("RGB-D folder: intrinsics outside sane bounds or the image are refused",
          "[opencv][rgbd][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "seq";
  writeRgbd(dir, "moving", 1);
  auto f = std::make_unique<FrameSlot>();
  SECTION("tiny focal length: refused at open") {
    test::writeText(dir + "/intrinsics.txt", "1e-30 1e-30 325.5 253.5\n");
    RgbdFolderReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()) == dir + "/intrinsics.txt: fx 1e-30 outside 10..100000 px");
  }
  SECTION("principal point outside the image: refused at the first frame") {
    // 640x480 images: cx 600 would be plausible, but the images here are 320x240.
    test::writeText(dir + "/intrinsics.txt", "259 259 600 120\n");
    writeSmallRgbdFrame(dir, "000000");
    RgbdFolderReader reader;
    REQUIRE(reader.open(dir.c_str()));
    CHECK(reader.next(*f) == ReadStatus::Error);
    CHECK(std::string(reader.error()) ==
          dir + "/intrinsics.txt: principal point 600,120 outside the 320x240 image");
  }
  SECTION("intrinsics.txt or groundtruth.txt that is a folder: named, not ignored") {
    RgbdFolderReader control;
    REQUIRE(control.open(dir.c_str()));
    std::remove((dir + "/intrinsics.txt").c_str());
    REQUIRE(::mkdir((dir + "/intrinsics.txt").c_str(), 0755) == 0);
    RgbdFolderReader reader;
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()) == dir + "/intrinsics.txt: not a regular file");
    REQUIRE(::rmdir((dir + "/intrinsics.txt").c_str()) == 0);
    std::remove((dir + "/groundtruth.txt").c_str());
    REQUIRE(::mkdir((dir + "/groundtruth.txt").c_str(), 0755) == 0);
    CHECK_FALSE(reader.open(dir.c_str()));
    CHECK(std::string(reader.error()) == dir + "/groundtruth.txt: not a regular file");
  }
}

TEST_CASE("RGB-D and OTB writers refuse a folder that holds a recording", "[opencv][bad]") {
  TempDir tmp;
  const std::string dir = tmp / "seq";
  writeRgbd(dir, "moving", 3);
  RgbdFolderWriter rgbd;
  CHECK_FALSE(rgbd.open(dir.c_str()));
  CHECK(std::string(rgbd.error()) ==
        dir + ": already holds a recording (rgb); write to a new or empty folder");
  OtbFolderWriter otb;
  CHECK_FALSE(otb.open(dir.c_str()));
  CHECK(std::string(otb.error()).find("already holds a recording") != std::string::npos);
  RgbdFolderReader reader;  // untouched
  REQUIRE(reader.open(dir.c_str()));
  CHECK(reader.frameCount() == 3);
}

TEST_CASE("BoBoT video writer: frame size, write errors, frame rate", "[opencv][bobot][bad]") {
  TempDir tmp;
  auto slot = std::make_unique<FrameSlot>();
  SECTION("a frame of another size is refused (OpenCV would drop it)") {
    BobotVideoWriter w;
    REQUIRE(w.open((tmp / "v.avi").c_str(), 30.0));
    auto src = synth("moving", 1);
    REQUIRE(src->next(*slot) == ReadStatus::Ok);
    REQUIRE(w.write(*slot));
    slot->rgb.resize(320, 240);
    CHECK_FALSE(w.write(*slot));
    CHECK(std::string(w.error()) == tmp / "v.avi" + ": frame 1 is 320x240, the video is 640x480");
  }
  SECTION("a file cut short by a size limit is an error at close") {
    struct rlimit old {};
    REQUIRE(::getrlimit(RLIMIT_FSIZE, &old) == 0);
    auto oldHandler = std::signal(SIGXFSZ, SIG_IGN);
    BobotVideoWriter w;
    REQUIRE(w.open((tmp / "capped.avi").c_str(), 30.0));
    struct rlimit capped = old;
    capped.rlim_cur = 400000;  // about 10 frames of MJPG
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &capped) == 0);
    auto src = synth("moving", 40);
    bool wrote = true;
    while (src->next(*slot) == ReadStatus::Ok) wrote = wrote && w.write(*slot);
    const bool closed = w.close();
    REQUIRE(::setrlimit(RLIMIT_FSIZE, &old) == 0);
    std::signal(SIGXFSZ, oldHandler);
    CHECK(wrote);  // OpenCV does not tell
    CHECK_FALSE(closed);
    const std::string e = w.error();
    INFO(e);
    CHECK(e.find(tmp / "capped.avi" + ": only ") == 0);
    CHECK(e.find(" of 40 frames written could be read back") != std::string::npos);
  }
  SECTION("the source's frame rate: frames read back 1/30 s apart") {
    auto src = synth("moving", 3);
    BobotVideoWriter w;
    REQUIRE(w.open((tmp / "v.avi").c_str(), src->nominalFps()));
    while (src->next(*slot) == ReadStatus::Ok) REQUIRE(w.write(*slot));
    REQUIRE(w.close());
    BobotVideoReader r;
    REQUIRE(r.open((tmp / "v.avi").c_str()));
    CHECK(r.nominalFps() == Approx(30.0));
    for (uint64_t want : {0u, 33333u, 66667u}) {
      REQUIRE(r.next(*slot) == ReadStatus::Ok);
      CHECK(slot->timeUs == want);
    }
  }
}

TEST_CASE("BoBoT video reader: a video shorter than its ground truth is an error",
          "[opencv][bobot][bad]") {
  TempDir tmp;
  const std::string avi = tmp / "cut.avi";
  auto slot = std::make_unique<FrameSlot>();
  {
    auto src = synth("moving", 20);
    BobotVideoWriter w;
    REQUIRE(w.open(avi.c_str(), 30.0));
    while (src->next(*slot) == ReadStatus::Ok) REQUIRE(w.write(*slot));
    REQUIRE(w.close());
  }
  // Cut the file to half its size: the header may announce 20 frames or none (the index
  // at the end is gone); either way the ground truth holds 20 boxes.
  const std::string bytes = test::readText(avi);
  test::writeText(avi, bytes.substr(0, bytes.size() / 2));
  BobotVideoReader r;
  REQUIRE(r.open(avi.c_str()));
  int n = 0;
  ReadStatus st;
  while ((st = r.next(*slot)) == ReadStatus::Ok) ++n;
  CHECK(st == ReadStatus::Error);
  CHECK(n < 20);
  // A cut through a frame leaves that frame damaged; a cut between frames ends the video.
  const std::string e = r.error();
  CHECK((e == avi + ": video ends at frame " + std::to_string(n) + " of 20" ||
         e.rfind(avi + ": frame " + std::to_string(n) + " is damaged (", 0) == 0));
  SourceOptions skip;  // skipping counts the missing frames instead
  skip.skipBadFrames = true;
  BobotVideoReader s;
  REQUIRE(s.open(avi.c_str(), skip));
  int m = 0;
  while (s.next(*slot) == ReadStatus::Ok) ++m;
  CHECK(m == n);
  CHECK(s.skippedFrames() == 20 - n);
}

TEST_CASE(
    "randomised scenes over the real stills: a still or the room behind, the target "
    "in front of it in the first frame, textures cut from the real videos",
    "[opencv][rand][shared]") {
  const std::string data = test::sharedDataDir();
  if (!test::pathExists(data + "/kinect-stills") || !test::pathExists(data + "/otb")) {
    CUETRACK_SKIP("shared data absent (" << data << ")");
  }
  auto slot = std::make_unique<FrameSlot>();
  int onStill = 0;
  for (int seed = 1; seed <= 6; ++seed) {
    const std::string spec = "rand:" + std::to_string(seed) + ":" + data;
    INFO(spec);
    RandomSceneReader r;
    if (!r.open(spec.c_str())) FAIL(r.error());
    const std::string name = r.name();
    CHECK(name.rfind("rand-" + std::to_string(seed), 0) == 0);
    const bool still =
        name.find("-nyu") != std::string::npos || name.find("-tum") != std::string::npos;
    onStill += still;
    REQUIRE(r.next(*slot) == ReadStatus::Ok);
    CHECK(r.frameCount() == 150);
    CHECK(r.scene()->truth().visibleFraction() > 0.5f);
    // The target's own pixels read its depth, in front of the still.
    const Box& g = slot->groundTruth;
    REQUIRE_FALSE(g.empty());
    const uint16_t d =
        slot->depthMm.data()[static_cast<int>(g.y + g.h / 2) * slot->depthMm.width() +
                             static_cast<int>(g.x + g.w / 2)];
    CHECK((d == 0 || std::fabs(d - r.scene()->truth().centreMm[2]) < 400.f));
  }
  CHECK(onStill >= 3);  // 7 stills and the room: most draws are over a still
  RandomSceneReader bad;
  CHECK_FALSE(bad.open(("rand:1:" + data + "/otb").c_str()));
  CHECK(std::string(bad.error()).find("has no kinect-stills/ and otb/") != std::string::npos);
}
