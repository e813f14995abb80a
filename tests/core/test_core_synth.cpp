// End to end on the synthetic RGB-D scenes of drivers/synth (640x480, Kinect depth
// model): every preset tracks a plainly moving target; in 3D a target that a
// same-textured twin crosses at another depth is kept; no allocation in any run.
#include <catch2/catch.hpp>
#include <cstdlib>

#include "AllocCounter.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;

namespace {
Tracker tracker;
FrameSlot slot;

struct Stats {
  int frames = 0, hits = 0;
  int framesAfter = 0, hitsAfter = 0;  // from frame `after` of runScene on
  double overlapAfter = 0;             // ... and the overlaps summed over them
  int absentWhileHidden = 0;  // frames the target is hidden and reported so (Lost, or occluded)
  int scored = 0;             // frames right as the benchmark scores them: a hit where the
                              // target is visible, reported absent where it is not
  int lastHidden = -1;        // the last frame with the target hidden
  int foundAgainAt = -1;      // the first hit after it
  double overlapSum = 0;
  // Per scene frame: flagged depthPredicted, and the overlap (frame 0, the init, neither).
  static constexpr int kMaxFrames = 300;
  bool depthPredictedAt[kMaxFrames] = {};
  float overlapAt[kMaxFrames] = {};
  uint64_t allocations = 0;
  float hitRate() const {
    return frames ? static_cast<float>(hits) / static_cast<float>(frames) : 0.f;
  }
  float scoredRate() const {
    return frames ? static_cast<float>(scored) / static_cast<float>(frames) : 0.f;
  }
  float hitRateAfter() const {
    return framesAfter ? static_cast<float>(hitsAfter) / static_cast<float>(framesAfter) : 0.f;
  }
};

// stride > 1: only every stride-th frame reaches the tracker (a slower camera: the
// target moves stride times as far between frames); rgbOnly: its depth is withheld;
// sceneSeed > 0: the scene's own seed (else the tracker's); backwards: played from the
// last frame to the first, the timestamps mirrored so they still increase (as
// `cuetrack-bench --reverse`).
Stats runScene(const char* scene, const TrackerConfig& config, uint64_t seed, int frames,
               int after = 1 << 30, int stride = 1, bool rgbOnly = false, uint64_t sceneSeed = 0,
               bool backwards = false) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  spec.frameCount = frames;
  REQUIRE(frames <= Stats::kMaxFrames);
  static SyntheticSource* src = nullptr;
  // One source object reused (placement into static storage: no heap in the loop).
  alignas(SyntheticSource) static unsigned char storage[sizeof(SyntheticSource)];
  if (src != nullptr) src->~SyntheticSource();
  src = new (storage) SyntheticSource(spec, sceneSeed > 0 ? sceneSeed : seed);
  auto play = [&](int k) {  // the k-th frame played
    REQUIRE(src->render(backwards ? frames - 1 - k : k, slot));
  };
  Stats s;
  REQUIRE(tracker.configure(config, seed) == ConfigError::None);
  play(0);
  const uint64_t firstUs = slot.timeUs;
  if (backwards) slot.timeUs = 0;
  const test::AllocScope scope;
  Frame first = slot.frame();
  if (rgbOnly) first.depthMm = DepthView{};
  REQUIRE(tracker.init(first, slot.groundTruth) == InitError::None);
  for (int k = 1; k < frames; ++k) {
    play(k);
    if (backwards) slot.timeUs = firstUs - slot.timeUs;
    if (slot.index % stride != 0) continue;
    Frame f = slot.frame();
    if (rgbOnly) f.depthMm = DepthView{};
    const TrackResult r = tracker.update(f);
    const float o = overlap(r.box, slot.groundTruth);
    s.overlapSum += o;
    s.hits += o > 1.f / 3.f ? 1 : 0;
    ++s.frames;
    if (slot.index >= after) {
      s.overlapAfter += o;
      s.hitsAfter += o > 1.f / 3.f ? 1 : 0;
      ++s.framesAfter;
    }
    s.depthPredictedAt[slot.index] = r.depthPredicted;
    s.overlapAt[slot.index] = o;
    const bool absent = r.state == TrackState::Lost || r.occluded;
    if (slot.groundTruth.empty() && absent) ++s.absentWhileHidden;
    s.scored += slot.groundTruth.empty() ? (absent ? 1 : 0)
                                         : (r.state == TrackState::Tracking && o > 1.f / 3.f);
    if (slot.groundTruth.empty()) {
      s.lastHidden = slot.index;
      s.foundAgainAt = -1;
    } else if (s.lastHidden >= 0 && s.foundAgainAt < 0 && o > 1.f / 3.f) {
      s.foundAgainAt = slot.index;
    }
  }
  s.allocations = scope.allocations();
  return s;
}

// The moving scene with its seed fixed (1, as in cuetrack-bench), every stride-th frame.
Stats runMoving(const TrackerConfig& config, uint64_t seed, int frames, int stride, bool rgbOnly) {
  return runScene("moving", config, seed, frames, 1 << 30, stride, rgbOnly, 1);
}

Stats runScene(const char* scene, Preset preset, uint64_t seed, int frames) {
  return runScene(scene, presetConfig(preset), seed, frames);
}

}  // namespace

bool emulated() {
  return std::getenv("CUETRACK_EMULATED") != nullptr;  // under qemu: fewer, shorter runs
}

bool sanitized() {
  return std::getenv("CUETRACK_SANITIZED") != nullptr;  // ASan/UBSan: fewer seeds
}

// Lean runs, under qemu and under the sanitizers: there the end-to-end runs prove what
// those builds are for, the host's bits on another ISA (tracks are identical on every
// platform: test_core_tracker's golden hashes) and no memory error, leak or undefined
// behaviour along each scene's path. So one seed, the configurations under test only, every
// scene to its event: the controls (a switch turned off, to show a check discriminates) and
// the means over many seeds are the host's quality checks. The same bits make each per-seed
// check of seed 1 hold there as it holds on the host (CUETRACK_SANITIZED=1 or
// CUETRACK_EMULATED=1 on the host build runs a lean build's cases at native speed).
bool lean() {
  return emulated() || sanitized();
}

TEST_CASE("the allocation counter sees allocations in this program (positive control)", "[alloc]") {
  // The zero-allocation checks of this program mean something only if this is not 0.
  CHECK(test::controlAllocations() >= 1);
}

TEST_CASE("every preset tracks the synthetic moving target", "[core][e2e]") {
  for (int i = 0; i < kNumPresets; ++i) {
    const Preset p = static_cast<Preset>(i);
    // Lean: under qemu 1.1 and best on 10 frames; under the sanitizers every preset (each
    // its own code path) on 30 frames.
    if (emulated() && p != Preset::Test1_1 && p != Preset::Best) continue;
    const int frames = emulated() ? 10 : sanitized() ? 30 : 90;
    const Stats s = runScene("moving", p, 11, frames);
    INFO("preset " << presetName(p) << ": hit rate " << s.hitRate() << ", mean overlap "
                   << s.overlapSum / s.frames);
    REQUIRE(s.frames == frames - 1);
    REQUIRE(s.hitRate() >= 0.98f);
    REQUIRE(s.allocations == 0);
  }
}

TEST_CASE("best in 2D keeps a target that moves twice as far per frame", "[core][e2e][motion]") {
  // The moving scene given every other frame, colour only (best falls back to 2D, where
  // the background-aware filter tracks alone): the target moves up to ~0.3 of its side
  // per frame. The particle path (filterLeads2d off) keeps it with the fast-motion
  // particles alone: the control, without them and without the correlation cue (which
  // keeps it too), loses it in about half the runs.
  TrackerConfig fastOnly = presetConfig(Preset::Best);
  fastOnly.filterLeads2d = false;
  fastOnly.correlationCue = false;
  TrackerConfig control = fastOnly;
  control.fastMotion = false;
  // Lean: seed 1, best and fast motion alone, 30 frames; no control.
  const int frames = emulated() ? 30 : 60;
  const int seeds = lean() ? 1 : 8;
  float controlHits = 0.f;
  for (int k = 0; k < seeds; ++k) {
    const uint64_t seed = 1 + static_cast<uint64_t>(k);
    const Stats best = runMoving(presetConfig(Preset::Best), seed, frames, 2, true);
    const Stats on = runMoving(fastOnly, seed, frames, 2, true);
    const Stats off = lean() ? Stats{} : runMoving(control, seed, frames, 2, true);
    INFO("seed " << seed << ": hit rate " << best.hitRate() << " best, " << on.hitRate()
                 << " with fast motion alone, " << off.hitRate() << " without either");
    REQUIRE(on.frames == (frames - 1) / 2);
    REQUIRE(best.hitRate() >= 0.95f);
    REQUIRE(on.hitRate() >= 0.95f);
    REQUIRE(best.allocations == 0);
    REQUIRE(on.allocations == 0);
    controlHits += off.hitRate() / static_cast<float>(seeds);
  }
  INFO("control's mean hit rate " << controlHits);
  if (!lean()) REQUIRE(controlHits <= 0.7f);
}

TEST_CASE("best in 3D keeps a target seen at 7.5 fps", "[core][e2e][motion]") {
  // The moving scene given every fourth frame (7.5 fps, with depth): the AR(1) model
  // does not reach where the target is next. Seeds 1-8: best keeps it in every frame; the
  // fast-motion particles alone (no correlation cue) 0.77-1.0, mean 0.92; without either
  // 0.50-0.73, mean 0.61 (seeds 1-2, as under the sanitizers: 0.98 against 0.70). At 30 fps
  // the two are the same bit for bit.
  TrackerConfig fastOnly = presetConfig(Preset::Best);
  fastOnly.correlationCue = false;
  TrackerConfig control = fastOnly;
  control.fastMotion = false;
  // Lean: seed 1, best and fast motion alone; no control; the 30 fps identity kept.
  const int stride = 4, frames = 90;
  const int seeds = lean() ? 1 : 8;
  float bestHits = 0.f, onHits = 0.f, controlHits = 0.f;
  for (int k = 0; k < seeds; ++k) {
    const uint64_t seed = 1 + static_cast<uint64_t>(k);
    const Stats best = runMoving(presetConfig(Preset::Best), seed, frames, stride, false);
    const Stats on = runMoving(fastOnly, seed, frames, stride, false);
    const Stats off = lean() ? Stats{} : runMoving(control, seed, frames, stride, false);
    INFO("seed " << seed << ": hit rate " << best.hitRate() << " best, " << on.hitRate()
                 << " with fast motion alone, " << off.hitRate() << " without either");
    REQUIRE(on.frames == (frames - 1) / stride);
    REQUIRE(best.allocations == 0);
    REQUIRE(on.allocations == 0);
    bestHits += best.hitRate() / static_cast<float>(seeds);
    onHits += on.hitRate() / static_cast<float>(seeds);
    controlHits += off.hitRate() / static_cast<float>(seeds);
  }
  INFO("mean hit rate " << bestHits << " best, " << onHits << " with fast motion alone, "
                        << controlHits << " without either");
  REQUIRE(bestHits >= 0.95f);
  REQUIRE(onHits >= 0.9f);
  if (!lean()) REQUIRE(controlHits <= onHits - 0.2f);
  const Stats a = runMoving(fastOnly, 3, 20, 1, false);
  const Stats b = runMoving(control, 3, 20, 1, false);
  REQUIRE(a.overlapSum == b.overlapSum);
}

TEST_CASE("best follows a target crossing the frame at 40 px a frame", "[core][e2e][motion]") {
  // The fast scene: a 40 px wide target moving 40 px a frame, turning every 12 frames. The
  // particles' motion noise does not reach where it is next; the correlation cue's map
  // (1.5 sides around the last estimate) does. Seeds 1-5: best keeps it in all five (hit
  // rates 0.91-0.97, mean 0.95, since the filter tracks in 3D: 0.93-1.0 with the template);
  // the control, best without the cue, 0.52-0.68 (mean 0.59). Under qemu one seed, 60
  // frames: 0.90 against the control's 0.61, so 0.85 there (the filter's first turns).
  // Lean: seed 1, 60 frames (five turns), best alone; no control.
  const int seeds = lean() ? 1 : 5;
  const int frames = lean() ? 60 : 150;
  TrackerConfig control = presetConfig(Preset::Best);
  control.correlationCue = false;
  float bestHits = 0.f, controlHits = 0.f;
  int kept = 0;
  for (uint64_t seed = 1; seed <= static_cast<uint64_t>(seeds); ++seed) {
    const Stats on = runScene("fast", presetConfig(Preset::Best), seed, frames);
    const Stats off = lean() ? Stats{} : runScene("fast", control, seed, frames);
    INFO("seed " << seed << ": hit rate " << on.hitRate() << " with, " << off.hitRate()
                 << " without");
    CHECK(on.allocations == 0);
    kept += on.hitRate() >= 0.7f ? 1 : 0;
    bestHits += on.hitRate() / static_cast<float>(seeds);
    controlHits += off.hitRate() / static_cast<float>(seeds);
  }
  INFO("mean hit rate " << bestHits << " with, " << controlHits << " without; " << kept << " of "
                        << seeds << " seeds kept");
  CHECK(bestHits >= (lean() ? 0.85f : 0.9f));
  if (!lean()) CHECK(bestHits >= controlHits + 0.25f);
  CHECK(kept >= seeds - 1);
}

TEST_CASE("best finds a target again that comes back elsewhere", "[core][e2e][reacquire]") {
  // The leave-return scene: the target leaves the view on the right at about frame 45 and
  // comes back from the left 30 frames later, fully in view from about frame 90. While
  // lost, the correlation template searches the whole image, and search windows on a
  // surface far off the target's depth (the wall, the floor) are not scored. Seeds 1-12:
  // found again and held from frame 110 on in all 12 (without the depth check on search
  // windows, 10: two seeds confirmed a patch of the wall while the target was away).
  // Lean: seed 1, the whole scene (gone, searched for, found again).
  constexpr int kAfter = 110;
  const uint64_t seeds = lean() ? 1 : 12;
  int found = 0;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Stats s = runScene("leave-return", presetConfig(Preset::Best), seed, 150, kAfter);
    const float after = s.hitRateAfter();
    INFO("seed " << seed << ": hit rate after frame " << kAfter << " " << after);
    CHECK(s.allocations == 0);
    CHECK(s.absentWhileHidden >= 10);  // it knows the target is gone
    found += after >= 0.9f ? 1 : 0;
  }
  INFO(found << " of " << seeds << " seeds found the target again");
  CHECK(found >= (seeds >= 12 ? 11 : static_cast<int>(seeds)));
}

TEST_CASE("3D keeps the target when a same-textured twin crosses it", "[core][e2e]") {
  // Over scene and tracker seeds 1-10. The paper's 2.1 has no guard against a cloud split
  // between two places: in about one seed of twenty (seed 19 of 1-20 before the weak
  // classifiers' density floor, seed 5 after) the estimate falls between target and twin
  // and drifts off; best (lost detection) keeps every seed.
  // Lean: seed 1, best alone (2.1's path is the golden hashes'), the whole crossing.
  const uint64_t seeds = lean() ? 1 : 10;
  for (Preset p : {Preset::Test2_1, Preset::Best}) {
    if (lean() && p != Preset::Best) continue;
    int kept = 0;
    for (uint64_t seed = 1; seed <= seeds; ++seed) {
      const Stats s = runScene("twin-crossing", p, seed, 150);
      INFO("preset " << presetName(p) << ", seed " << seed << ": hit rate " << s.hitRate()
                     << ", mean overlap " << s.overlapSum / s.frames);
      kept += s.hitRate() >= 0.95f ? 1 : 0;
      if (p == Preset::Best) CHECK(s.hitRate() >= 0.95f);
      CHECK(s.allocations == 0);
    }
    INFO("preset " << presetName(p) << ": " << kept << " of " << seeds << " seeds kept");
    CHECK(kept >= static_cast<int>(seeds) - 1);
  }
}

TEST_CASE("best re-acquires the target after an occluder has hidden it", "[core][e2e][reacquire]") {
  // The box hides the target completely from about frame 67 to 90; from frame 96 on it
  // is in full view again. Without re-acquisition the tracker never finds it again.
  // Seeds 1-10: hit rate after frame 100 0.94-1.0, mean 0.99 (0.80 over seeds 1-20 before
  // the search while lost kept off surfaces far from the target's depth). Lean: seed 1, the
  // whole scene (hidden, lost, found again); no control.
  constexpr int kAfter = 100;
  const uint64_t seeds = lean() ? 1 : 10;
  float sum = 0.f;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Stats s = runScene("occlusion", presetConfig(Preset::Best), seed, 150, kAfter);
    const float after = s.hitRateAfter();
    INFO("seed " << seed << ": hit rate " << s.hitRate() << ", after frame " << kAfter << " "
                 << after << ", reported absent while hidden " << s.absentWhileHidden);
    CHECK(s.absentWhileHidden >= 10);  // it knows the target is gone
    CHECK(s.allocations == 0);
    sum += after;
  }
  INFO("mean hit rate after frame " << kAfter << ": " << sum / static_cast<float>(seeds));
  CHECK(sum / static_cast<float>(seeds) >= (seeds >= 5 ? 0.9f : 0.5f));
  // Control: the same seeds without lost detection (and so without re-acquisition).
  TrackerConfig noLost = presetConfig(Preset::Best);
  noLost.lostDetection = false;
  // 0.0 on each of 5 (ASan: 10 s a run); lean: none.
  if (lean()) return;
  const uint64_t controlSeeds = 5;
  float sumNoLost = 0.f;
  for (uint64_t seed = 1; seed <= controlSeeds; ++seed) {
    const Stats n = runScene("occlusion", noLost, seed, 150, kAfter);
    sumNoLost += n.hitRateAfter();
  }
  const float meanNoLost = sumNoLost / static_cast<float>(controlSeeds);
  INFO("without lost detection, mean hit rate after frame " << kAfter << ": " << meanNoLost);
  CHECK(meanNoLost <= 0.5f);
}

TEST_CASE("best holds the target behind a look-alike that crosses in front of it",
          "[core][e2e][occlude]") {
  // The look-alike (1.6 m) covers the target (2.4 m) partly from frame 46 to 104 and wholly
  // from 67 to 84. Seeds 1-5, scored as cuetrack-bench scores (a hit where the target is
  // visible and tracked, "not visible" where it is hidden): 0.99-1.0 with the occlusion
  // gate; 0.48-0.83, mean 0.69, without it (lost for ~45 frames from ~55, after learning
  // the look-alike's edge; seeds 1-3: 0.61). Lean: seed 1, the whole crossing; no control.
  const uint64_t seeds = lean() ? 1 : 5;
  TrackerConfig noGate = presetConfig(Preset::Best);
  noGate.occlusionGate = false;
  float sum = 0.f, sumNoGate = 0.f;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Stats s = runScene("lookalike", presetConfig(Preset::Best), seed, 150);
    const Stats n = lean() ? Stats{} : runScene("lookalike", noGate, seed, 150);
    INFO("seed " << seed << ": scored " << s.scoredRate() << " (without the gate " << n.scoredRate()
                 << "), reported absent while hidden " << s.absentWhileHidden);
    CHECK(s.absentWhileHidden >= 18);  // of 21 hidden frames
    CHECK(s.allocations == 0);
    sum += s.scoredRate();
    sumNoGate += n.scoredRate();
  }
  const float mean = sum / static_cast<float>(seeds);
  const float meanNoGate = sumNoGate / static_cast<float>(seeds);
  INFO("mean " << mean << ", without the occlusion gate " << meanNoGate);
  CHECK(mean >= 0.9f);
  if (!lean()) CHECK(mean >= meanNoGate + 0.15f);
}

TEST_CASE("best says when the target's depth is predicted, and holds it by colour",
          "[core][e2e][occlude]") {
  // The no-depth scene: the target reads no depth in frames 40-109, moving meanwhile.
  // Seeds 1-3: flagged on all of them and on no other; mean overlap over them 0.86-0.89
  // (best with its depth withheld from the start: 0.85 over the whole scene). Lean: seed 1
  // (under qemu 60 frames: the depth lost, 20 frames without it).
  const uint64_t seeds = lean() ? 1 : 3;
  const int frames = emulated() ? 60 : 150;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Stats s = runScene("no-depth", presetConfig(Preset::Best), seed, frames);
    int inside = 0, flaggedInside = 0, flaggedOutside = 0;
    double overlapInside = 0;
    for (int f = 1; f < frames; ++f) {
      if (f >= 40 && f <= 109) {
        ++inside;
        flaggedInside += s.depthPredictedAt[f] ? 1 : 0;
        overlapInside += s.overlapAt[f];
      } else {
        flaggedOutside += s.depthPredictedAt[f] ? 1 : 0;
      }
    }
    INFO("seed " << seed << ": flagged " << flaggedInside << " of " << inside
                 << " depthless frames, " << flaggedOutside << " others; overlap there "
                 << overlapInside / inside);
    CHECK(flaggedInside == inside);
    CHECK(flaggedOutside <= 2);  // at most the frame the depth comes back, and one more
    CHECK(overlapInside / inside >= 0.7);
    CHECK(s.allocations == 0);
  }
}

TEST_CASE("best reports a first box on a plain wall lost within a few frames",
          "[core][e2e][reacquire]") {
  // The untextured scene's wall is one grey: a box on it (left of the grey cylinder) has
  // nothing the classifier can tell from the windows beside it. Its score there stays
  // near 0.5, above the lost threshold, so only PeakContrast can catch it. In 3D and in
  // 2D (depth withheld), several seeds; the textured target is kept (the tests above).
  SceneSpec spec;
  REQUIRE(makeScene("untextured", &spec));
  constexpr int kFrames = 40;
  spec.frameCount = kFrames;
  alignas(SyntheticSource) static unsigned char storage[sizeof(SyntheticSource)];
  SyntheticSource* src = new (storage) SyntheticSource(spec, 1);
  const Box wall{100.f, 300.f, 40.f, 40.f};
  for (const bool rgbOnly : {false, true}) {
    // Lean: seed 1 in each of 3D and 2D.
    for (uint64_t seed = 1; seed <= (lean() ? 1u : 3u); ++seed) {
      REQUIRE(tracker.configure(presetConfig(Preset::Best), seed) == ConfigError::None);
      REQUIRE(src->render(0, slot));
      REQUIRE(overlap(wall, slot.groundTruth) == 0.f);  // the box misses the target
      Frame first = slot.frame();
      if (rgbOnly) first.depthMm = DepthView{};
      REQUIRE(tracker.init(first, wall) == InitError::None);
      int lostAt = -1, trackedAfter = 0;
      for (int k = 1; k < kFrames; ++k) {
        REQUIRE(src->render(k, slot));
        Frame f = slot.frame();
        if (rgbOnly) f.depthMm = DepthView{};
        const TrackResult r = tracker.update(f);
        if (r.state == TrackState::Lost && lostAt < 0) lostAt = k;
        if (lostAt >= 0 && r.state == TrackState::Tracking) ++trackedAfter;
      }
      INFO((rgbOnly ? "2D" : "3D") << " seed " << seed << ": lost at frame " << lostAt
                                   << ", tracking again on " << trackedAfter << " frames");
      CHECK(lostAt > 0);
      // Within the lost detector's count of misses: 4 in 3D, best's lostAfter2d (25) in
      // 2D, where the confidence alone is a weaker witness.
      const int within =
          (rgbOnly ? presetConfig(Preset::Best).lostAfter2d : tuning::lost::kLostAfter) + 1;
      CHECK(lostAt <= within);
      CHECK(trackedAfter <= 2);  // not "found" again on the wall for long
    }
  }
  src->~SyntheticSource();
}

TEST_CASE("best's cylinder follows a target whose width changes as it turns",
          "[core][e2e][occlude]") {
  // A box yawing 90 degrees: 107 px wide side-on, 38 px end-on at frame 149. From frame
  // 100 (yaw 60 degrees, width 0.7x) a cylinder of the first frame's size is too wide
  // (scene and tracker seed 3: fixed size ~0.44 mean overlap there, measured ~0.87).
  constexpr int kAfter = 100;
  // Lean: the measured size alone (no fixed-size control).
  const Stats s = runScene("turn", presetConfig(Preset::Best), 3, 150, kAfter);
  TrackerConfig fixedSize = presetConfig(Preset::Best);
  fixedSize.adaptCylinderSize = false;
  const Stats f = lean() ? Stats{} : runScene("turn", fixedSize, 3, 150, kAfter);
  const double measured = s.overlapAfter / s.framesAfter;
  const double fixed = lean() ? 0.0 : f.overlapAfter / f.framesAfter;
  INFO("mean overlap from frame " << kAfter << ": measured size " << measured << ", fixed size "
                                  << fixed);
  CHECK(measured >= 0.6);
  if (!lean()) CHECK(fixed < measured - 0.2);
  CHECK(s.allocations == 0);
}

TEST_CASE("best's cylinder grows back when a flat target turns face-on again",
          "[core][e2e][occlude]") {
  // A flat box turns from face-on (68 px) to 78 degrees (26 px, frame ~80) and back to
  // face-on by frame 149. Once the estimate had fallen to under half the target's width,
  // the silhouette's default window could not hold it, and the box stayed ~26 px wide
  // (mean overlap ~0.35 from frame 110 on); the wide window measures it again.
  constexpr int kAfter = 110;
  // Lean: seed 1, the whole turn and back.
  const uint64_t seeds = lean() ? 1 : 3;
  double sum = 0.0;
  for (uint64_t seed = 1; seed <= seeds; ++seed) {
    const Stats s = runScene("flat-turn", presetConfig(Preset::Best), seed, 150, kAfter);
    const double after = s.overlapAfter / s.framesAfter;
    INFO("seed " << seed << ": mean overlap from frame " << kAfter << " " << after);
    CHECK(s.allocations == 0);
    sum += after;
  }
  INFO("mean over seeds " << sum / static_cast<double>(seeds));
  CHECK(sum / static_cast<double>(seeds) >= 0.6);
}
