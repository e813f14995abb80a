// The tracker on real data (shared data; skipped when absent): on real Kinect depth, a
// chair of the NYU still panned by StillPanReader, where best's measured cylinder size
// must keep the user's box, legs included, and beat the fixed cylinder, and the TUM
// keyboard, where best's mode guard must keep a cloud that splits; on real RGB, BoBoT's
// still panda, where 2D tracking must hold the size.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdlib>
#include <memory>
#include <string>

#include "AllocCounter.hpp"
#include "SharedData.hpp"
#include "Skip.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"
#include "cuetrack/drivers/OpenCvSources.hpp"

using namespace cuetrack;

namespace {

Tracker tracker;  // large: static storage

struct Run {
  double meanOverlap = 0.0;
  int frames = 0, hits = 0;
  uint64_t allocations = 0;
};

// Opens `spec` and starts the tracker on its first frame and ground-truth box.
template <typename Source>
std::unique_ptr<FrameSlot> start(Source& source, const std::string& spec, const TrackerConfig& cfg,
                                 uint64_t seed) {
  if (!source.open(spec.c_str())) FAIL(source.error());
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(source.next(*slot) == ReadStatus::Ok);
  REQUIRE(tracker.configure(cfg, seed) == ConfigError::None);
  REQUIRE(tracker.init(slot->frame(), slot->groundTruth) == InitError::None);
  return slot;
}

Run track(const std::string& spec, const TrackerConfig& cfg, uint64_t seed) {
  StillPanReader source;
  const auto slot = start(source, spec, cfg, seed);
  REQUIRE(tracker.uses3d());
  Run r;
  double sum = 0.0;
  const test::AllocScope scope;
  uint64_t inside = 0;
  while (source.next(*slot) == ReadStatus::Ok) {
    const uint64_t before = scope.allocations();
    const TrackResult t = tracker.update(slot->frame());
    inside += scope.allocations() - before;
    const float o = overlap(t.box, slot->groundTruth);
    sum += o;
    r.hits += o > 1.f / 3.f ? 1 : 0;
    ++r.frames;
  }
  r.allocations = inside;
  r.meanOverlap = r.frames ? sum / r.frames : 0.0;
  return r;
}

struct BoxError {
  double size = 0.0;    // mean |ln(w / w_true)| + |ln(h / h_true)|
  double centre = 0.0;  // mean distance of the centres [px]
};

// The box's errors over the first `frames` frames of a BoBoT video.
BoxError boxError(const std::string& avi, const TrackerConfig& cfg, uint64_t seed, int frames) {
  BobotVideoReader source;
  const auto slot = start(source, avi, cfg, seed);
  BoxError e;
  int n = 0;
  while (n < frames && source.next(*slot) == ReadStatus::Ok) {
    const TrackResult t = tracker.update(slot->frame());
    REQUIRE(t.box.w > 0.f);
    const Box& g = slot->groundTruth;
    e.size += std::fabs(std::log(t.box.w / g.w)) + std::fabs(std::log(t.box.h / g.h));
    e.centre += std::hypot((t.box.x + 0.5 * t.box.w) - (g.x + 0.5 * g.w),
                           (t.box.y + 0.5 * t.box.h) - (g.y + 0.5 * g.h));
    ++n;
  }
  REQUIRE(n == frames);
  e.size /= n;
  e.centre /= n;
  return e;
}

// BoBoT H (the still panda); absent without the shared data.
std::string pandaVideo() {
  return test::sharedDataDir() + "/bobot/Vid_H_panda.avi";
}

}  // namespace

TEST_CASE("the allocation counter sees allocations in this program (positive control)", "[alloc]") {
  // The zero-allocation checks of this program mean something only if this is not 0.
  CHECK(test::controlAllocations() >= 1);
}

TEST_CASE("in 2D, corner-anchored negatives hold a still target's size", "[core][e2e][shared]") {
  // BoBoT H: the panda and the camera stand still (one ground-truth box for all frames).
  // With only concentric shrunk negatives the classifier scores a window on the panda's
  // head above the whole panda, and the size drifts there (docs/algorithm.md); negatives
  // anchored at the estimate's corners and edges (1.1 as shipped) must drift less.
  const std::string avi = pandaVideo();
  if (!test::pathExists(avi)) CUETRACK_SKIP("shared data absent (" << avi << ")");
  const TrackerConfig shipped = presetConfig(Preset::Test1_1);
  TrackerConfig centred = shipped;
  centred.anchoredNegatives2d = false;
  const uint64_t seeds = 3;
  double corner = 0.0, centre = 0.0;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    corner += boxError(avi, shipped, seed, 150).size;
    centre += boxError(avi, centred, seed, 150).size;
  }
  INFO("mean |ln size error|: corner-anchored negatives " << corner / seeds << ", centred only "
                                                          << centre / seeds);
  // Measured (seeds 1-3): size 0.026 against 0.050.
  CHECK(corner < 0.9 * centre);
}

TEST_CASE("best keeps a real chair's box on real Kinect depth", "[core][e2e][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/nyu-joinmap";
  if (!test::pathExists(dir)) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  // The wing chair of still 5; its box includes the legs, which the silhouette's middle
  // columns do not see (the floor shows between them).
  const std::string spec =
      "pan:" + dir + "/color/5.png," + dir + "/depth/5.pgm,302,102,186,240,518,519,325.5,253.5:150";
  TrackerConfig fixed = presetConfig(Preset::Best);
  fixed.adaptCylinderSize = false;
  const uint64_t seeds = std::getenv("CUETRACK_SANITIZED") != nullptr ? 1 : 2;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Run best = track(spec, presetConfig(Preset::Best), seed);
    const Run ref = track(spec, fixed, seed);
    INFO("seed " << seed << ": best " << best.meanOverlap << ", fixed size " << ref.meanOverlap);
    CHECK(best.frames == 149);
    CHECK(best.hits == best.frames);
    CHECK(best.allocations == 0);
    CHECK(best.meanOverlap > 0.87);
    CHECK(best.meanOverlap > ref.meanOverlap);
  }
}
