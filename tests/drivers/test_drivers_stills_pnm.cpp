// Real Kinect v1 stills through our own PGM loader (no OpenCV): the NYU depth maps are
// 16-bit big-endian PGM in mm. Skipped (reported as such) when the shared data is absent.
#include <catch2/catch.hpp>

#include <algorithm>
#include <memory>
#include <vector>

#include "SharedData.hpp"
#include "Skip.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;

TEST_CASE("NYU Kinect stills: depth PGM loads with Kinect v1 ranges", "[stills][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/nyu-joinmap";
  if (!test::pathExists(dir)) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  // The documented calibration of these stills is the project's Kinect default.
  CHECK(kKinectV1Intrinsics.fx == 518.0f);
  CHECK(kKinectV1Intrinsics.fy == 519.0f);
  CHECK(kKinectV1Intrinsics.cx == 325.5f);
  CHECK(kKinectV1Intrinsics.cy == 253.5f);
  std::vector<uint8_t> buf;
  std::vector<uint16_t> depth(640 * 480);
  char err[256] = "";
  for (int i = 1; i <= 5; ++i) {
    const std::string path = dir + "/depth/" + std::to_string(i) + ".pgm";
    INFO(path);
    REQUIRE(rec::readFile(path.c_str(), buf, err, sizeof err));
    rec::PnmHeader h;
    REQUIRE(rec::parsePnmHeader(buf.data(), buf.size(), &h, err, sizeof err));
    REQUIRE(h.width == 640);
    REQUIRE(h.height == 480);
    REQUIRE(rec::decodePnm16(buf.data(), buf.size(), h, rec::Endian::Big, depth.data(), err,
                             sizeof err));
    std::vector<uint16_t> valid;
    for (uint16_t d : depth)
      if (d) valid.push_back(d);
    const double holes = 1.0 - static_cast<double>(valid.size()) / depth.size();
    std::sort(valid.begin(), valid.end());
    // Kinect v1 reads ~0.5 m to ~10 m; indoor scenes have a median of a few metres and
    // holes (shadows, out of range) on 5-50 % of the pixels.
    CHECK(valid.front() >= 400);
    CHECK(valid.back() <= 10000);
    CHECK(valid[valid.size() / 2] > 1000);
    CHECK(valid[valid.size() / 2] < 6000);
    CHECK(holes > 0.05);
    CHECK(holes < 0.5);
    // Little-endian reading of the same bytes would be nonsense: most values > 10 m.
    REQUIRE(rec::decodePnm16(buf.data(), buf.size(), h, rec::Endian::Little, depth.data(), err,
                             sizeof err));
    int absurd = 0;
    for (uint16_t d : depth) absurd += d > 10000;
    CHECK(absurd > 100000);
  }
}
