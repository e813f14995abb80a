// The tracker on real Kinect depth: a chair of the NYU still (shared data) panned by
// StillPanReader. best's measured cylinder size must keep the user's box, legs included,
// and beat the fixed cylinder; skipped when the shared data is absent.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <memory>
#include <string>

#include "AllocCounter.hpp"
#include "SharedData.hpp"
#include "cuetrack/core/Tracker.hpp"
#include "cuetrack/drivers/OpenCvSources.hpp"

using namespace cuetrack;

namespace {

Tracker tracker;  // large: static storage

struct Run {
  double meanOverlap = 0.0;
  int frames = 0, hits = 0;
  uint64_t allocations = 0;
};

Run track(const std::string& spec, const TrackerConfig& cfg, uint64_t seed) {
  StillPanReader source;
  if (!source.open(spec.c_str())) FAIL(source.error());
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(source.next(*slot) == ReadStatus::Ok);
  tracker.configure(cfg, seed);
  REQUIRE(tracker.init(slot->frame(), slot->groundTruth) == InitError::None);
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

}  // namespace

TEST_CASE("best keeps a real chair's box on real Kinect depth", "[core][e2e][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/nyu-joinmap";
  if (!test::pathExists(dir)) {
    WARN("shared data absent (" << dir << "): skipped");
    return;
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

TEST_CASE("best's mode guard keeps a keyboard whose cloud splits", "[core][e2e][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/tum-fr1";
  if (!test::pathExists(dir)) {
    WARN("shared data absent (" << dir << "): skipped");
    return;
  }
  // The TUM desk's keyboard: repetitive keys in front of the table. On seed 2 the cloud
  // splits at frame 100 between the keyboard and the table above it; the weighted mean
  // falls between the two (confidence 0.76 -> 0.29), lost detection fires and the target
  // is not found again for ~40 frames. With the guard the estimate stays on the keyboard.
  const std::string spec = "pan:" + dir + "/1.png," + dir +
                           "/1_depth.png,202,257,184,50,517.3,516.5,318.6,255.3,0.2:150";
  TrackerConfig noGuard = presetConfig(Preset::Best);
  noGuard.modeGuard = false;
  const Run control = track(spec, noGuard, 2);
  INFO("without the guard: " << control.hits << " hits of " << control.frames);
  CHECK(control.hits < control.frames - 10);  // control: this seed does split
  const uint64_t first = std::getenv("CUETRACK_SANITIZED") != nullptr ? 2 : 1;
  for (uint64_t seed = first; seed <= 3; ++seed) {
    const Run best = track(spec, presetConfig(Preset::Best), seed);
    INFO("seed " << seed << ": " << best.hits << " hits of " << best.frames << ", overlap "
                 << best.meanOverlap);
    CHECK(best.hits >= best.frames - 5);  // seed 2 still drops 4 frames at the split
    CHECK(best.meanOverlap > 0.85);
    CHECK(best.allocations == 0);
  }
}
