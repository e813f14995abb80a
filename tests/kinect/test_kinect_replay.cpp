// The live Kinect code path replaying recordings through Debian's fakenect.
//
// fakenect keeps its state in globals (one pass over one recording per process), so
// each TEST_CASE here runs in a process of its own: tests/kinect/CMakeLists.txt
// registers one ctest entry per tag, with LD_LIBRARY_PATH=<fakenect dir> and
// FAKENECT_PATH=<a recording generated at test time by make_fakenect_recording>.
#include <catch2/catch.hpp>

#include <csignal>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>

#include "AllocCounter.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"
#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/KinectSource.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#if defined(CUETRACK_TEST_HAVE_RGBD)
#include "cuetrack/drivers/OpenCvSources.hpp"
#endif

using namespace cuetrack;

namespace {

// Large objects: static storage.
KinectSource gKinect;
FakenectReader gReader;
FrameSlot gLive;
FrameSlot gRef;

const char* recording() {
  const char* p = std::getenv("FAKENECT_PATH");
  return p ? p : "";
}

bool sameColour(const FrameSlot& a, const FrameSlot& b) {
  return a.rgb.width() == b.rgb.width() && a.rgb.height() == b.rgb.height() &&
         std::memcmp(a.rgb.data(), b.rgb.data(),
                     sizeof(Rgb8) * static_cast<size_t>(a.rgb.width() * a.rgb.height())) == 0;
}

bool sameDepth(const FrameSlot& a, const FrameSlot& b) {
  return a.hasDepth == b.hasDepth && a.depthMm.width() == b.depthMm.width() &&
         a.depthMm.height() == b.depthMm.height() &&
         std::memcmp(
             a.depthMm.data(), b.depthMm.data(),
             sizeof(uint16_t) * static_cast<size_t>(a.depthMm.width() * a.depthMm.height())) == 0;
}

void openReference() {
  INFO("FAKENECT_PATH=" << recording());
  REQUIRE(gReader.open(recording()));
}

}  // namespace

TEST_CASE("fakenect replay through the live path delivers the recorded frames, then End",
          "[replay][delivers]") {
  REQUIRE(kinectReplayLibraryLoaded());
  openReference();
  KinectOptions options;
  REQUIRE(gKinect.open(options));
  CHECK(gKinect.replay());
  CHECK_FALSE(gKinect.depthRegistered());  // fakenect serves raw 11-bit only

  {
    test::ThreadAllocScope control;  // positive control of the per-thread counter
    int* p = new int(1);
    CHECK(control.allocations() == 1);
    delete p;
  }
  const uint64_t processAllocsBefore = test::allocationCount();
  int frames = 0;
  bool allColour = true, allDepth = true, allTimes = true;
  uint64_t consumerAllocs = 0;
  ReadStatus st = ReadStatus::Ok;
  for (;;) {
    // Count this (consumer) thread only: fakenect itself allocates per frame on the
    // event thread (it reads each file with malloc), which is not our code.
    test::ThreadAllocScope scope;
    st = gKinect.next(gLive);
    if (frames > 0) consumerAllocs += scope.allocations();
    if (st != ReadStatus::Ok) break;
    REQUIRE(gReader.next(gRef) == ReadStatus::Ok);
    allColour = allColour && sameColour(gLive, gRef);
    allDepth = allDepth && sameDepth(gLive, gRef);
    allTimes = allTimes && gLive.timeUs == gRef.timeUs;
    CHECK(gLive.index == frames);
    ++frames;
  }
  INFO(gKinect.error());
  CHECK(st == ReadStatus::End);
  CHECK(gReader.next(gRef) == ReadStatus::End);  // every recorded frame arrived
  CHECK(frames >= 2);
  CHECK(allColour);
  CHECK(allDepth);
  CHECK(allTimes);
  CHECK(consumerAllocs == 0);
  // fakenect's event thread did allocate meanwhile: the per-thread count is what
  // separates our consumer path from the replay library.
  CHECK(test::allocationCount() > processAllocsBefore);
  // The end of the recording is a stopped stream: it stays ended, without waiting.
  CHECK(gKinect.next(gLive) == ReadStatus::End);
  const KinectStats s = gKinect.stats();
  CHECK(s.delivered == static_cast<uint64_t>(frames));
  CHECK(s.dropped == 0);
  CHECK(s.unpaired == 0);
  gKinect.close();
}

TEST_CASE("tracking over the live path gives the same tracks as reading the recording",
          "[replay][tracks]") {
  REQUIRE(kinectReplayLibraryLoaded());
  openReference();
  // Reference run: the recording read directly.
  static Tracker tracker;
  TrackerConfig config = presetConfig(Preset::Best);
  config.numParticles = 300;  // same result for any size; keeps qemu runs short
  constexpr uint64_t kSeed = 42;
  constexpr int kMaxBoxes = 64;
  Box refBoxes[kMaxBoxes];
  int refCount = 0;
  REQUIRE(tracker.configure(config, kSeed) == ConfigError::None);
  REQUIRE(gReader.next(gRef) == ReadStatus::Ok);
  REQUIRE(gRef.hasGroundTruth);
  const Box start = gRef.groundTruth;
  REQUIRE(tracker.init(gRef.frame(), start) == InitError::None);
  while (refCount < kMaxBoxes && gReader.next(gRef) == ReadStatus::Ok)
    refBoxes[refCount++] = tracker.update(gRef.frame()).box;
  REQUIRE(refCount >= 2);

  // Live run over the same recording, same seed.
  KinectOptions options;
  REQUIRE(gKinect.open(options));
  REQUIRE(tracker.configure(config, kSeed) == ConfigError::None);
  REQUIRE(gKinect.next(gLive) == ReadStatus::Ok);
  REQUIRE(tracker.init(gLive.frame(), start) == InitError::None);
  int liveCount = 0;
  int equal = 0;
  while (liveCount < kMaxBoxes && gKinect.next(gLive) == ReadStatus::Ok) {
    const Box b = tracker.update(gLive.frame()).box;
    if (liveCount < refCount) {
      const Box& r = refBoxes[liveCount];
      if (b.x == r.x && b.y == r.y && b.w == r.w && b.h == r.h) ++equal;
    }
    ++liveCount;
  }
  CHECK(liveCount == refCount);
  CHECK(equal == refCount);
  gKinect.close();
}

TEST_CASE("a stream that stalls mid-run gives a clear error within the stall timeout",
          "[replay][stall]") {
  // The recording has a long pause; fakenect sleeps through it like a stalled device.
  REQUIRE(kinectReplayLibraryLoaded());
  KinectOptions options;
  options.stallTimeoutMs = 300;
  REQUIRE(gKinect.open(options));
  // The caller's idle hook runs between the wait's 100 ms slices (serial heartbeats).
  static int idleCalls = 0;
  gKinect.setIdleHook(
      [](void*) {
        ++idleCalls;
        return false;
      },
      nullptr);
  int frames = 0;
  ReadStatus st;
  while ((st = gKinect.next(gLive)) == ReadStatus::Ok) ++frames;
  CHECK(idleCalls >= 2);  // after 100 and 200 ms of the stall (and of any slow frame)
  const std::string why = gKinect.error();
  INFO(why);
  CHECK(st == ReadStatus::Error);
  CHECK(frames >= 1);
  CHECK(why.find("no colour+depth pair within 0.3 s") != std::string::npos);
  CHECK(why.find('\n') == std::string::npos);
  CHECK(gKinect.next(gLive) == ReadStatus::Error);  // sticky, no second wait
  gKinect.close();                                  // returns once fakenect's sleep ends: bounded
}

TEST_CASE("a stop request ends the stream cleanly", "[replay][stop]") {
  REQUIRE(kinectReplayLibraryLoaded());
  KinectOptions options;
  REQUIRE(gKinect.open(options));
  REQUIRE(gKinect.next(gLive) == ReadStatus::Ok);
  // From another thread, as a signal handler would.
  std::thread stopper([] { gKinect.requestStop(); });
  stopper.join();
  CHECK(gKinect.next(gLive) == ReadStatus::End);
  CHECK(std::string(gKinect.error()).find("stopped") != std::string::npos);
  gKinect.close();
  CHECK_FALSE(gKinect.isOpen());
}

TEST_CASE("SIGINT stops the stream through the stopRequested hook", "[replay][signal]") {
  REQUIRE(kinectReplayLibraryLoaded());
  platform::installStopSignals();
  KinectOptions options;
  options.stopRequested = &platform::stopRequested;
  REQUIRE(gKinect.open(options));
  REQUIRE(gKinect.next(gLive) == ReadStatus::Ok);
  // The event thread blocks SIGINT, so the handler runs on an application thread.
  REQUIRE(std::raise(SIGINT) == 0);
  CHECK(platform::stopRequested());
  CHECK(gKinect.next(gLive) == ReadStatus::End);
  CHECK(std::string(gKinect.error()).find("stopped") != std::string::npos);
  gKinect.close();
}

TEST_CASE("depth-only mode with a rate divisor delivers every other depth frame",
          "[replay][depth-only]") {
  REQUIRE(kinectReplayLibraryLoaded());
  openReference();
  const int total = gReader.frameCount();
  REQUIRE(total > 0);
  KinectOptions options;
  options.streams = KinectStreams::DepthOnly;
  options.rateDivisor = 2;
  REQUIRE(gKinect.open(options));
  int frames = 0;
  bool depthOnly = true;
  while (gKinect.next(gLive) == ReadStatus::Ok) {
    depthOnly = depthOnly && gLive.hasDepth && gLive.rgb.width() == 0;
    ++frames;
  }
  INFO(gKinect.error());
  CHECK(depthOnly);
  CHECK(frames == (total + 1) / 2);
  CHECK(gKinect.stats().skippedByRate == static_cast<uint64_t>(total / 2));
  CHECK(gKinect.stats().colourFrames == 0);
  gKinect.close();
}

TEST_CASE("colour-only mode delivers colour frames without depth", "[replay][colour-only]") {
  REQUIRE(kinectReplayLibraryLoaded());
  openReference();
  KinectOptions options;
  options.streams = KinectStreams::ColourOnly;
  REQUIRE(gKinect.open(options));
  int frames = 0;
  bool same = true;
  while (gKinect.next(gLive) == ReadStatus::Ok) {
    REQUIRE(gReader.next(gRef) == ReadStatus::Ok);
    same = same && !gLive.hasDepth && sameColour(gLive, gRef);
    ++frames;
  }
  INFO(gKinect.error());
  CHECK(same);
  CHECK(frames == gReader.frameCount());
  CHECK(gKinect.stats().depthFrames == 0);
  gKinect.close();
}

TEST_CASE(
    "fakenect without a usable FAKENECT_PATH, or asked for registered depth, fails "
    "with one clear line",
    "[replay][misuse]") {
  REQUIRE(kinectReplayLibraryLoaded());
  KinectOptions options;
  options.depthMode = KinectDepthMode::Registered;
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find("raw 11-bit depth only") != std::string::npos);

  options.depthMode = KinectDepthMode::Auto;
  const std::string saved = recording();
  setenv("FAKENECT_PATH", "", 1);
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find("FAKENECT_PATH is not set") != std::string::npos);
  setenv("FAKENECT_PATH", "/nonexistent/recording", 1);
  CHECK_FALSE(gKinect.open(options));
  CHECK(std::string(gKinect.error()).find("/nonexistent/recording/INDEX.txt") != std::string::npos);
  setenv("FAKENECT_PATH", saved.c_str(), 1);
}

TEST_CASE("cuetrack-record's copy of a replayed recording reads back as the original",
          "[replay][copy]") {
  const char* copy = std::getenv("CUETRACK_KINECT_COPY");
  REQUIRE(copy != nullptr);
  static FakenectReader copyReader;
  openReference();
  INFO("copy: " << copy);
  REQUIRE(copyReader.open(copy));
  int frames = 0;
  bool same = true;
  while (gReader.next(gRef) == ReadStatus::Ok) {
    REQUIRE(copyReader.next(gLive) == ReadStatus::Ok);
    same = same && sameColour(gLive, gRef) && sameDepth(gLive, gRef) && gLive.timeUs == gRef.timeUs;
    ++frames;
  }
  CHECK(copyReader.next(gLive) == ReadStatus::End);
  CHECK(frames >= 2);
  CHECK(same);
}

#if defined(CUETRACK_TEST_HAVE_RGBD)
TEST_CASE("cuetrack-record --format rgbd writes the replayed frames as an RGB-D folder",
          "[replay][copy-rgbd]") {
  const char* copy = std::getenv("CUETRACK_KINECT_COPY");
  REQUIRE(copy != nullptr);
  static RgbdFolderReader copyReader;
  openReference();
  INFO("copy: " << copy);
  REQUIRE(copyReader.open(copy));
  int frames = 0;
  bool same = true;
  while (copyReader.next(gLive) == ReadStatus::Ok) {
    REQUIRE(gReader.next(gRef) == ReadStatus::Ok);
    same = same && sameColour(gLive, gRef) && sameDepth(gLive, gRef);
    ++frames;
  }
  CHECK(frames == 5);  // --frames 5
  CHECK(same);
}
#endif
