// Any video, any size, end to end through the real cuetrack: a 1280x720 MJPG .avi with
// --box and a 1920x1080 mp4v .mp4 with its OTB ground truth beside it (both written here
// with cv::VideoWriter: a textured rectangle moving right), tracked with every box in the
// CSV in the video's own pixels, overlapping the truth; --out over that ground truth is
// refused (exit 2). And --source camera without a camera: exit 1, one line naming the
// device.
#include <catch2/catch.hpp>

#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "MovingRectVideo.hpp"
#include "Process.hpp"
#include "Skip.hpp"
#include "TempDir.hpp"
#include "TestPrograms.hpp"

using namespace cuetrack;
using namespace cuetrack::test;

namespace {

constexpr int kTimeoutMs = 120000;  // generous: 2 cores shared by many builds
constexpr int kFrames = 20;

int run(std::vector<const char*> argv, const std::string& err) {
  argv.push_back(nullptr);
  const int status = runToEnd(argv.data(), "/dev/null", err.c_str(), kTimeoutMs);
  REQUIRE(status != kRunNotStarted);
  return status;
}

// Tracks video (with extra args) and checks the CSV: a row per frame, every box in the
// video's own pixels, on the moving rectangle.
void requireTrackedInSourcePixels(const std::string& video, int width, int height,
                                  std::vector<const char*> extra, const TempDir& tmp) {
  const std::string csv = tmp / "tracks.csv", err = tmp / "err";
  std::vector<const char*> argv = {CUETRACK_APP_BIN, "--source",  video.c_str(),
                                   "--out",          csv.c_str(), "--quiet"};
  argv.insert(argv.end(), extra.begin(), extra.end());
  const int rc = run(argv, err);
  INFO(readText(err));
  REQUIRE(rc == 0);
  const std::vector<std::string> rows = lines(readText(csv));
  REQUIRE(rows.size() == kFrames + 1);  // the header, then one row per frame
  double overlapSum = 0.0;
  float maxRight = 0.f;
  for (int i = 0; i < kFrames; ++i) {
    const std::string& row = rows[static_cast<size_t>(i) + 1];
    char state[32] = "";
    unsigned seq = 0;
    unsigned long long timeUs = 0;
    int x = 0, y = 0, w = 0, h = 0;
    INFO(row);
    REQUIRE(std::sscanf(row.c_str(), "%u,%llu,%31[^,],%d,%d,%d,%d", &seq, &timeUs, state, &x, &y,
                        &w, &h) == 7);
    REQUIRE(std::string(state) == "tracking");
    const Box b{static_cast<float>(x), static_cast<float>(y), static_cast<float>(w),
                static_cast<float>(h)};
    overlapSum += overlap(b, movingRectBox(i, width, height));
    if (b.x + b.w > maxRight) maxRight = b.x + b.w;
  }
  const Box first = movingRectBox(0, width, height);
  CAPTURE(overlapSum / kFrames, maxRight);
  REQUIRE(overlapSum / kFrames > 0.6);          // on the target, in the source's pixels
  REQUIRE(maxRight > static_cast<float>(640));  // beyond the tracker's 640 px: not its pixels
  REQUIRE(maxRight > first.x + first.w);        // it followed the rectangle right
}

}  // namespace

TEST_CASE("a 1280x720 .avi and a 1920x1080 .mp4 track with boxes in their own pixels") {
  TempDir tmp;
  const std::string avi = tmp / "hd.avi";
  REQUIRE(
      writeMovingRectVideo(avi, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 1280, 720, kFrames));
  const Box b = movingRectBox(0, 1280, 720);
  char box[64];
  std::snprintf(box, sizeof box, "%d,%d,%d,%d", cvRound(b.x), cvRound(b.y), cvRound(b.w),
                cvRound(b.h));
  requireTrackedInSourcePixels(avi, 1280, 720, {"--box", box}, tmp);
  // A box large enough in the video's pixels but not once scaled down: the line says so.
  const std::string tinyErr = tmp / "tiny";
  REQUIRE(run({CUETRACK_APP_BIN, "--source", avi.c_str(), "--box", "100,100,4,4"}, tinyErr) == 4);
  CHECK(readText(tinyErr).find("(the image is 1280x720, scaled down to 640x360 for the tracker, "
                               "where the box is 2.0x2.0 px; give a larger box)") !=
        std::string::npos);

  const std::string mp4 = tmp / "fullhd.mp4";
  if (!writeMovingRectVideo(mp4, cv::VideoWriter::fourcc('m', 'p', '4', 'v'), 1920, 1080,
                            kFrames)) {
    CUETRACK_SKIP("this OpenCV cannot write mp4v .mp4: the 1920x1080 part is not tested");
  }
  writeText(tmp / "fullhd.txt", otbGroundTruth(kFrames, 1920, 1080));  // the target from it
  requireTrackedInSourcePixels(mp4, 1920, 1080, {}, tmp);
  // That ground truth is an input: --out over it is refused before anything opens.
  const std::string gt = tmp / "fullhd.txt", err = tmp / "err";
  REQUIRE(run({CUETRACK_APP_BIN, "--source", mp4.c_str(), "--out", gt.c_str()}, err) == 2);
  CHECK(readText(err).find("is the same file as --source's ground truth") != std::string::npos);
}

TEST_CASE("--source camera without a camera: exit 1, one line naming the device") {
  TempDir tmp;
  const std::string err = tmp / "err";
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "camera:/nonexistent/video7", "--frames", "1"}, err) ==
          1);
  const std::vector<std::string> said = lines(readText(err));
  REQUIRE(said.size() == 1);
  CHECK(said[0].find("camera /nonexistent/video7: no such device") != std::string::npos);
  REQUIRE(run({CUETRACK_APP_BIN, "--source", "camera:x"}, err) == 2);
  CHECK(readText(err).find("expected camera, camera:N or camera:/dev/videoN") != std::string::npos);
}
