// The real libfreenect on a machine without a Kinect: a clear error, never a hang.
// Skipped (reported as such) where a Kinect is plugged in or fakenect is loaded.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "Skip.hpp"
#include "cuetrack/drivers/KinectSource.hpp"

using namespace cuetrack;

namespace {
KinectSource gKinect;
FrameSlot gSlot;
}  // namespace

TEST_CASE("without a Kinect, open() fails with one clear line and next() does not hang",
          "[kinect][nodevice]") {
  if (kinectReplayLibraryLoaded()) {
    CUETRACK_SKIP("fakenect is loaded: the no-device test needs the real libfreenect");
  }
  char err[160] = "";
  const int n = countKinects(err, sizeof err);
  if (n < 0) {
    // libusb unusable (no /dev/bus/usb): still a clean, named failure.
    CHECK(std::strlen(err) > 0);
  } else if (n > 0) {
    CUETRACK_SKIP("a Kinect is plugged in: the no-device test needs none");
  }
  KinectOptions options;
  CHECK_FALSE(gKinect.open(options));
  const std::string why = gKinect.error();
  INFO(why);
  CHECK(why.find('\n') == std::string::npos);
  if (n == 0) CHECK(why.find("no Kinect found") != std::string::npos);
  CHECK_FALSE(gKinect.isOpen());
  CHECK(gKinect.next(gSlot) == ReadStatus::Error);

  // Device selection errors are named too.
  options.serial = "A00000000000000";
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find('\n') == std::string::npos);
}

TEST_CASE("bad options are refused before touching USB", "[kinect][nodevice]") {
  KinectOptions options;
  options.rateDivisor = 0;
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find("rate divisor") != std::string::npos);
  options.rateDivisor = 1;
  options.setTilt = true;
  options.tiltDeg = 40.f;
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find("tilt") != std::string::npos);
}

TEST_CASE("option names parse, unknown names are refused", "[kinect][nodevice]") {
  KinectStreams s{};
  CHECK(parseKinectStreams("depth", &s));
  CHECK(s == KinectStreams::DepthOnly);
  CHECK(parseKinectStreams("colour", &s));
  CHECK(s == KinectStreams::ColourOnly);
  CHECK_FALSE(parseKinectStreams("ir", &s));
  KinectDepthMode d{};
  CHECK(parseKinectDepthMode("raw", &d));
  CHECK(d == KinectDepthMode::Raw);
  CHECK_FALSE(parseKinectDepthMode("mm", &d));
  KinectLed l{};
  CHECK(parseKinectLed("blink-red-yellow", &l));
  CHECK(l == KinectLed::BlinkRedYellow);
  CHECK_FALSE(parseKinectLed("blue", &l));
  // The bandwidth figures docs/kinect.md quotes.
  CHECK(kinectUsbLoadMBps(KinectStreams::Both) == Approx(21.9).margin(0.05));
  CHECK(kinectUsbLoadMBps(KinectStreams::DepthOnly) == Approx(12.7).margin(0.05));
  CHECK(kinectUsbLoadMBps(KinectStreams::ColourOnly) == Approx(9.2).margin(0.05));
}
