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

// Opens `spec` and starts the tracker on its first frame and ground-truth box.
template <typename Source>
std::unique_ptr<FrameSlot> start(Source& source, const std::string& spec, const TrackerConfig& cfg,
                                 uint64_t seed) {
  if (!source.open(spec.c_str())) FAIL(source.error());
  auto slot = std::make_unique<FrameSlot>();
  REQUIRE(source.next(*slot) == ReadStatus::Ok);
  tracker.configure(cfg, seed);
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

constexpr int kWholeH = 411;  // BoBoT H: every frame after the first

}  // namespace

TEST_CASE("the allocation counter sees allocations in this program (positive control)", "[alloc]") {
  // The zero-allocation checks of this program mean something only if this is not 0.
  CHECK(test::controlAllocations() >= 1);
}

TEST_CASE("in 2D, corner-anchored negatives and the template anchor hold a still target's box",
          "[core][e2e][shared]") {
  // BoBoT H: the panda and the camera stand still (one ground-truth box for all frames).
  // With only concentric shrunk negatives the classifier scores a window on the panda's
  // head above the whole panda, and the size drifts there (docs/algorithm.md); negatives
  // anchored at the estimate's corners and edges (1.1 as shipped) must drift less, and
  // with the template anchor on top (best's 2D) the size must stay within a few percent;
  // the anchor's shift step must hold the centre closer than its size ladder alone.
  const std::string avi = pandaVideo();
  if (!test::pathExists(avi)) CUETRACK_SKIP("shared data absent (" << avi << ")");
  const TrackerConfig shipped = presetConfig(Preset::Test1_1);
  TrackerConfig centred = shipped, anchored = shipped;
  centred.anchoredNegatives2d = false;
  anchored.scaleAnchor2d = true;
  // The shift step is on in best only (2D here: no depth), so it is measured there.
  // Measured with the anchor correcting the reported box alone: a cloud that follows it
  // (the next test) holds the centre closer without the shift step too (0.99 px), and the
  // shift step's own part would drown in the run-to-run spread of three seeds.
  TrackerConfig best = presetConfig(Preset::Best);
  best.anchorMovesCloud = false;
  TrackerConfig sizeOnly = best;
  sizeOnly.templateShift = false;
  const uint64_t seeds = 3;
  double corner = 0.0, centre = 0.0, anchor = 0.0, shiftPx = 0.0, noShiftPx = 0.0;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    corner += boxError(avi, shipped, seed, 150).size;
    centre += boxError(avi, centred, seed, 150).size;
    anchor += boxError(avi, anchored, seed, 150).size;
    shiftPx += boxError(avi, best, seed, kWholeH).centre;
    noShiftPx += boxError(avi, sizeOnly, seed, kWholeH).centre;
  }
  INFO("mean |ln size error|: corner-anchored negatives " << corner / seeds << ", centred only "
                                                          << centre / seeds << ", with the anchor "
                                                          << anchor / seeds);
  INFO("mean centre error [px]: template anchor " << shiftPx / seeds << ", its size ladder only "
                                                  << noShiftPx / seeds);
  // Measured (seeds 1-3): size 0.026 against 0.050, with the anchor 0.024 (with 9 initial
  // positives 3% apart: 0.042 against 0.048). The centre is measured over the whole video:
  // since the 17 closer initial positives the classifier alone holds it to under a pixel
  // for the first 100 frames, and it drifts after the exposure change there: 0.80 px with
  // the shift step, 1.24 without.
  CHECK(corner < 0.9 * centre);
  CHECK(anchor / seeds < 0.05);
  CHECK(shiftPx < 0.8 * noShiftPx);
}

TEST_CASE("in 2D, a cloud that follows the template anchor keeps a still target's size",
          "[core][e2e][shared]") {
  // BoBoT H after the exposure change at frame ~100: the backlit panda's classifier pulls
  // each frame's mean 3-5% small, and the anchor, applied to the reported box alone, asks
  // for larger on nearly every frame without ever catching up. With the cloud moved by
  // part of each correction (best), the correction stays in the state.
  const std::string avi = pandaVideo();
  if (!test::pathExists(avi)) CUETRACK_SKIP("shared data absent (" << avi << ")");
  const TrackerConfig best = presetConfig(Preset::Best);
  REQUIRE(best.anchorMovesCloud);
  TrackerConfig reportOnly = best;
  reportOnly.anchorMovesCloud = false;
  const uint64_t seeds = 3;
  double follow = 0.0, report = 0.0;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    follow += boxError(avi, best, seed, kWholeH).size;
    report += boxError(avi, reportOnly, seed, kWholeH).size;
  }
  INFO("mean |ln size error| over H: cloud follows the anchor "
       << follow / seeds << ", reported box only " << report / seeds);
  // Measured (seeds 1-3): 0.026 against 0.041.
  CHECK(follow < 0.8 * report);
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

TEST_CASE("best's mode guard keeps a keyboard whose cloud splits", "[core][e2e][shared]") {
  const std::string dir = test::sharedDataDir() + "/kinect-stills/tum-fr1";
  if (!test::pathExists(dir)) {
    CUETRACK_SKIP("shared data absent (" << dir << ")");
  }
  // The TUM desk's keyboard: repetitive keys in front of the table. On seed 30 of 1-60
  // the cloud splits between the keyboard and the table above it; the weighted mean
  // falls between the two, lost detection fires and the target is not found again for a
  // while (112 hits of 149; before the weak classifiers' density floor it was seed 36 of
  // 1-40, before the boosting's candidate refresh seeds 4, 7 and 16 of 1-16). With the
  // guard the estimate stays on the keyboard (144 of 149 on seed 30, all on the others).
  const std::string spec = "pan:" + dir + "/1.png," + dir +
                           "/1_depth.png,202,257,184,50,517.3,516.5,318.6,255.3,0.2:150";
  TrackerConfig noGuard = presetConfig(Preset::Best);
  noGuard.modeGuard = false;
  const Run control = track(spec, noGuard, 30);
  INFO("without the guard: " << control.hits << " hits of " << control.frames);
  CHECK(control.hits < control.frames - 10);  // control: this seed does split
  const bool sanitized = std::getenv("CUETRACK_SANITIZED") != nullptr;
  for (const uint64_t seed : {30u, 4u, 1u}) {
    if (sanitized && seed != 30u) continue;
    const Run best = track(spec, presetConfig(Preset::Best), seed);
    INFO("seed " << seed << ": " << best.hits << " hits of " << best.frames << ", overlap "
                 << best.meanOverlap);
    if (seed == 30u) {
      CHECK(best.hits >= control.hits + 20);
      CHECK(best.hits >= best.frames - 10);
    } else {
      CHECK(best.hits == best.frames);
    }
    CHECK(best.meanOverlap > 0.85);
    CHECK(best.allocations == 0);
  }
}
