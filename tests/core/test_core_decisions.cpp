// The decisions Tracker wires rather than makes, each on its own: the miss rule, the hold
// behind an occluder, the search region, the space a new track runs in (and its
// fallback), the reseeder (particles at the cue's peak, the lost scan's tiles), the
// appearance cue's choice, and the configuration's validation.
#include <catch2/catch.hpp>

#include <cstdint>
#include <string>

#include "cuetrack/core/config/ConfigError.hpp"
#include "cuetrack/core/cues/AppearanceCue.hpp"
#include "cuetrack/core/filter/Reseeder.hpp"
#include "cuetrack/core/filter/SearchRegion.hpp"
#include "cuetrack/core/guards/Gate.hpp"
#include "cuetrack/core/guards/MissRule.hpp"
#include "cuetrack/core/guards/OcclusionHold.hpp"
#include "cuetrack/core/guards/PeakLevel.hpp"
#include "cuetrack/core/tracker/InitTarget.hpp"
#include "cuetrack/core/tracker/SpaceChoice.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"

using namespace cuetrack;

namespace {

constexpr int W = 160, H = 120;

Rgb8 gRgb[W * H];
uint16_t gDepth[W * H];
DepthMedian gMedian;
IntegralChannels gChannels;  // large: static storage
AppearanceCue gCue;
ParticleFilter gFilter;
Reseeder gReseeder;
Tracker gTracker;

// A block texture on gray, and a flat surface at depthMm (0: no depth).
Frame scene(uint16_t depthMm) {
  for (int y = 0; y < H; ++y)
    for (int x = 0; x < W; ++x) {
      const uint8_t g = static_cast<uint8_t>(((x / 8 + y / 8) % 2 != 0) ? 200 : 40);
      gRgb[y * W + x] = Rgb8{g, static_cast<uint8_t>(g / 2), static_cast<uint8_t>(255 - g)};
      gDepth[y * W + x] = depthMm;
    }
  Frame f;
  f.rgb = RgbView{gRgb, W, H, W};
  if (depthMm > 0) f.depthMm = DepthView{gDepth, W, H, W};
  f.intrinsics = CameraIntrinsics{130.f, 130.f, 80.f, 60.f};
  return f;
}

MissRule::Inputs tracked3d(float depthMm, float contrast) {
  MissRule::Inputs in;
  in.is3d = true;
  in.depthMm = depthMm;
  in.contrast = contrast;
  return in;
}

Particle at3d(float x, float y, float z) {
  Particle q;
  q.p[0] = x;
  q.p[1] = y;
  q.p[2] = z;
  q.size[0] = 200.f;
  q.size[1] = 300.f;
  return q;
}

}  // namespace

TEST_CASE("MissRule: a flat estimate, or a depth jump while tracking, is a miss",
          "[core][missrule]") {
  DepthGuard g;
  g.reset(2000.f);
  constexpr float kStandsOut = 1.f;
  CHECK_FALSE(MissRule::miss(tracked3d(2000.f, kStandsOut), g));
  CHECK(MissRule::miss(tracked3d(2000.f, 0.f), g));         // PeakContrast::flat
  CHECK(MissRule::miss(tracked3d(1400.f, kStandsOut), g));  // something in front
  MissRule::Inputs in2d = tracked3d(1400.f, kStandsOut);
  in2d.is3d = false;  // 2D: no depth to judge by
  CHECK_FALSE(MissRule::miss(in2d, g));
  in2d.contrast = 0.f;
  CHECK(MissRule::miss(in2d, g));
}

TEST_CASE("MissRule: found again, only an implausible depth is a miss", "[core][missrule]") {
  DepthGuard g;
  g.reset(2000.f);
  MissRule::Inputs in = tracked3d(1600.f, 1.f);
  in.wasLost = true;  // found again nearer: the target may have moved while hidden
  CHECK_FALSE(MissRule::miss(in, g));
  in.depthMm = 4000.f;  // the wall behind
  CHECK(MissRule::miss(in, g));
  in.wasLost = false;
  in.onProbation = true;
  CHECK(MissRule::miss(in, g));
  in.depthMm = 2400.f;
  CHECK_FALSE(MissRule::miss(in, g));
}

TEST_CASE("MissRule: on probation, a find unlike the target is a miss", "[core][missrule]") {
  DepthGuard g;
  g.reset(2000.f);
  MissRule::Inputs in = tracked3d(2000.f, 1.f);
  in.unlikeTarget = true;
  CHECK_FALSE(MissRule::miss(in, g));  // tracking: the filter's peak dips on a turning target
  in.onProbation = true;
  CHECK(MissRule::miss(in, g));
  in.unlikeTarget = false;
  CHECK_FALSE(MissRule::miss(in, g));
}

TEST_CASE("PeakLevel: unlike the target below half its usual peak, like it from there",
          "[core][peaklevel]") {
  PeakLevel p;
  p.reset();
  CHECK_FALSE(p.unlike(0.f));  // nothing learnt yet: nothing to judge by
  CHECK_FALSE(p.like(1.f));
  p.learnt(0.6f);
  CHECK(p.mean() == 0.6f);  // the first peak, not a blend from 0
  CHECK(p.unlike(0.29f));
  CHECK_FALSE(p.like(0.29f));
  CHECK_FALSE(p.unlike(0.31f));
  CHECK(p.like(0.31f));
  p.learnt(-1.f);  // no response: ignored
  CHECK(p.mean() == 0.6f);
  for (int i = 0; i < 100; ++i) p.learnt(0.2f);  // the target's look changed: follows it
  CHECK(p.mean() < 0.21f);
  CHECK_FALSE(p.unlike(0.15f));
  p.reset();
  CHECK_FALSE(p.unlike(0.f));
}

TEST_CASE("OcclusionHold: held where learnt, moved on at the learnt velocity, for kMaxHoldS",
          "[core][occlusionhold]") {
  OcclusionHold h;
  h.start(0, at3d(0.f, 0.f, 2000.f));
  // Learnt moving +300 mm/s in x for a second, 30 Hz.
  uint64_t t = 0;
  for (int i = 0; i <= 30; ++i, t += 33333)
    h.learnt(t, at3d(300.f * static_cast<float>(t) * 1e-6f, 0.f, 2000.f), true);
  const uint64_t learntUs = t - 33333;
  Particle last = at3d(300.f, 0.f, 2000.f);
  CHECK_FALSE(h.step(t, false, &last));  // not behind anything: not held
  REQUIRE(h.step(t, true, &last));
  CHECK(h.velocityMmPerS()[0] == Approx(300.f).margin(1.f));
  const uint64_t later = learntUs + 1000000;  // one second on
  REQUIRE(h.step(later, true, &last));
  CHECK(last.p[0] == Approx(600.f).margin(2.f));  // 300 + 300 mm/s x 1 s
  CHECK(last.p[2] == 2000.f);                     // the depth is kept
  // Held from t: beyond kMaxHoldS it is let go.
  const uint64_t tooLong = t + static_cast<uint64_t>(OcclusionHold::kMaxHoldS * 1e6f) + 1;
  CHECK_FALSE(h.step(tooLong, true, &last));
  h.stop();
  CHECK_FALSE(h.holding());
}

TEST_CASE("OcclusionHold: covered by a nearer surface over most of the box",
          "[core][occlusionhold]") {
  const Frame near = scene(1000);  // a surface a metre in front of the target
  const Particle q = at3d(0.f, 0.f, 2000.f);
  const Box box{40.f, 30.f, 40.f, 40.f};
  CHECK(OcclusionHold::covered(near.depthMm, box, q));
  const Frame behind = scene(2500);
  CHECK_FALSE(OcclusionHold::covered(behind.depthMm, box, q));
}

TEST_CASE("SearchRegion: the windows grown by their mean size, the cue's region, lost",
          "[core][searchregion]") {
  const Box windows[3] = {{50.f, 40.f, 10.f, 10.f}, {}, {60.f, 50.f, 10.f, 10.f}};
  // Mean size over all 3 (the empty one too): 20/3 px; grown kRoiMarginSides of it.
  const PixelRect r = SearchRegion::of(Span<const Box>(windows, 3), nullptr, false, W, H);
  const int grow = static_cast<int>(tuning::kRoiMarginSides * 20.f / 3.f);
  CHECK(r.x0 <= 50 - grow);
  CHECK(r.x0 >= 50 - grow - 1);
  CHECK(r.x1 >= 70 + grow);
  CHECK(r.y0 <= 40 - grow);
  const Box cue{0.f, 0.f, 20.f, 20.f};
  const PixelRect withCue = SearchRegion::of(Span<const Box>(windows, 3), &cue, false, W, H);
  CHECK(withCue.x0 == 0);
  CHECK(withCue.y0 == 0);
  CHECK(withCue.x1 == r.x1);
  const PixelRect lost = SearchRegion::of(Span<const Box>(windows, 3), nullptr, true, W, H);
  CHECK((lost.x0 == 0 && lost.y0 == 0 && lost.x1 == W && lost.y1 == H));
  // No window: the whole image rather than a degenerate region.
  const Box none1[1] = {Box{}};
  const PixelRect none = SearchRegion::of(Span<const Box>(none1, 1), nullptr, false, W, H);
  CHECK((none.x0 == 0 && none.y0 == 0 && none.x1 == W && none.y1 == H));
}

TEST_CASE("SpaceChoice: 3D when the frame carries it, else the fallback and why",
          "[core][spacechoice]") {
  TrackerConfig c = presetConfig(Preset::Best);
  const Box b{60.f, 40.f, 30.f, 30.f};
  SpaceChoice s = SpaceChoice::of(c, scene(1500), b, gMedian);
  CHECK(s.error == InitError::None);
  CHECK(s.is3d);
  CHECK(s.depthFeatures);
  CHECK_FALSE(s.fellBack);
  CHECK(s.surfaceMm == Approx(1500.f).margin(10.f));
  CHECK(s.numWeak == c.numWeakClassifiers);
  CHECK(s.lostAfter == LostDetector{}.lostAfter);
  // No depth: 2D RGB, with the fallback's M and lost count.
  s = SpaceChoice::of(c, scene(0), b, gMedian);
  CHECK(s.error == InitError::None);
  CHECK_FALSE(s.is3d);
  CHECK_FALSE(s.depthFeatures);
  CHECK(s.fellBack);
  CHECK(s.why == InitError::NoDepth);
  CHECK(s.numWeak == c.numWeakClassifiers2d);
  CHECK(s.lostAfter == c.lostAfter2d);
  // No intrinsics, or a box as wide as fx: the same fallback, for its own reason.
  Frame f = scene(1500);
  f.intrinsics = CameraIntrinsics{};
  CHECK(SpaceChoice::of(c, f, b, gMedian).why == InitError::NoIntrinsics);
  f = scene(1500);
  CHECK(SpaceChoice::of(c, f, Box{0.f, 0.f, 140.f, 100.f}, gMedian).why ==
        InitError::BoxTooWideFor3d);
  // Without fallbackTo2d the reason is the error.
  c = presetConfig(Preset::Test2_1);
  CHECK(SpaceChoice::of(c, scene(0), b, gMedian).error == InitError::NoDepth);
  f.intrinsics = CameraIntrinsics{};
  CHECK(SpaceChoice::of(c, f, b, gMedian).error == InitError::NoIntrinsics);
  // 2D RGB asked for: nothing to fall back from.
  s = SpaceChoice::of(presetConfig(Preset::Test1_1), scene(0), b, gMedian);
  CHECK((s.error == InitError::None && !s.is3d && !s.fellBack));
}

TEST_CASE("Reseeder: one particle in kEvery onto the window, moving as it jumped (2D)",
          "[core][reseeder]") {
  gFilter.setSize(200);
  Particle from;
  from.p[0] = 20.f;
  from.p[1] = 20.f;
  from.size[0] = from.size[1] = 10.f;
  gFilter.fill(from);
  Rng rng(5);
  const SearchView view{false, CameraIntrinsics{}, W, H};
  const Box c{100.f, 80.f, 16.f, 12.f};
  const int moved = gReseeder.place(c, from, 1.f / 30.f, true, view, gChannels, rng, gFilter);
  REQUIRE(moved == 200 / Reseeder::kEvery);
  for (int k = 0; k < moved; ++k) {
    const int i = gReseeder.index(k);
    CHECK(i % Reseeder::kEvery == Reseeder::kSlot);
    const Particle& q = gFilter[i];
    CHECK(q.size[0] == 16.f);
    CHECK(q.p[0] == Approx(108.f).margin(8.f));  // near c's centre, jittered
    CHECK(q.v[0] == q.p[0] - 20.f);              // px per frame, from where it was
    CHECK(gReseeder.windows()[k].w == 16.f);
  }
  CHECK(gFilter[0].p[0] == 20.f);  // the others stay
}

TEST_CASE("Reseeder: the lost scan's tiles cover the image, round and round", "[core][reseeder]") {
  const Box last{0.f, 0.f, 20.f, 20.f};
  const Reseeder::Tiles t = Reseeder::tiles(last, 3.f, W, H);
  CHECK(t.nx == 1 + static_cast<int>((160.f - 20.f) / 60.f));
  CHECK(t.ny == 1 + static_cast<int>((120.f - 20.f) / 60.f));
  gReseeder.restartScan();
  const Box first = gReseeder.nextTile(t);
  CHECK(first.x == 30.f);  // half a step in
  CHECK(first.y == 30.f);
  CHECK(first.w == 20.f);
  CHECK(gReseeder.nextTile(t).x == 90.f);
  for (int k = 2; k < t.count(); ++k) gReseeder.nextTile(t);
  CHECK(gReseeder.nextTile(t).x == first.x);  // back to the first
}

TEST_CASE("AppearanceCue: the filter tracks, the template scans in 3D, none when off",
          "[core][appearancecue]") {
  const Frame f = scene(0);
  gChannels.compute(f, PixelRect{0, 0, W, H}, false);
  const Box win{60.f, 40.f, 24.f, 24.f};
  gCue.start(false, true, false, f.rgb, gChannels.tables(), win);
  CHECK_FALSE(gCue.enabled());
  Box region;
  CHECK(gCue.searchRegion(false, win, &region) == nullptr);  // no cue: nothing to search
  CHECK_FALSE(gCue.scansImage(true));
  // 2D: the filter alone; it tracks and scans.
  gCue.start(true, true, false, f.rgb, gChannels.tables(), win);
  CHECK(gCue.isFilter());
  CHECK(gCue.trackingReady());
  CHECK(gCue.scanReady());
  CHECK(gCue.scanMinPeak() == tuning::dcf::kMinPeak);
  CHECK(gCue.scanStepSides() == CorrelationFilter::kPadding);
  CHECK(gCue.region(win).w == CorrelationFilter::region(win).w);
  REQUIRE(gCue.searchRegion(false, win, &region) == &region);  // tracking: around the window
  CHECK(region.w == CorrelationFilter::region(win).w);
  CHECK(gCue.searchRegion(true, win, &region) == nullptr);  // lost: the scan instead
  CHECK(gCue.scansImage(true));
  CHECK_FALSE(gCue.scansImage(false));
  const CueAnswer a2d = gCue.search(f.rgb, gChannels.tables(), win, true);
  CHECK(a2d.valid);
  CHECK(a2d.byFilter());
  CHECK(a2d.minPeak == tuning::dcf::kMinPeak);
  CHECK(a2d.strong());  // on the window it was learnt from
  CHECK(gCue.at(a2d, a2d.box.x + 0.5f * a2d.box.w, a2d.box.y + 0.5f * a2d.box.h) > 0.9f);
  // 3D: the filter tracks (one scale), the template scans.
  gCue.start(true, true, true, f.rgb, gChannels.tables(), win);
  CHECK(gCue.isFilter());
  const CueAnswer tracked = gCue.search(f.rgb, gChannels.tables(), win, false);
  CHECK(tracked.byFilter());
  CHECK(tracked.minPeak == tuning::dcf::kMinPeak);
  CHECK(gCue.region(win).w == CorrelationFilter::region(win).w);
  CHECK(gCue.scanMinPeak() == tuning::correlation::kMinPeak);
  CHECK(gCue.scanStepSides() == 3.f);
  const CueAnswer scanned = gCue.scan(f.rgb, gChannels.tables(), win);
  CHECK(scanned.valid);
  CHECK(scanned.byTemplate);
  CHECK_FALSE(scanned.byFilter());  // the peak level reads the filter's answers only
  CHECK(scanned.minPeak == tuning::correlation::kMinPeak);
  CHECK(scanned.peak > 0.9f);  // the template on the window it was learnt from
  // The template alone (no filter wanted).
  gCue.start(true, false, false, f.rgb, gChannels.tables(), win);
  CHECK_FALSE(gCue.isFilter());
  CHECK(gCue.trackingReady());
  CHECK(gCue.region(win).w == CorrelationCue::region(win).w);
  const CueAnswer byTemplate = gCue.search(f.rgb, gChannels.tables(), win, false);
  CHECK(byTemplate.valid);
  CHECK(byTemplate.byTemplate);
  CHECK(byTemplate.minPeak == tuning::correlation::kMinPeak);
  CHECK(byTemplate.peak > 0.9f);
}

TEST_CASE("initTarget: the start box within the image, or why none", "[core][init]") {
  const Frame f = scene(0);
  Box t;
  CHECK(initTarget(f.rgb, Box{-10.f, 100.f, 30.f, 40.f}, &t) == InitError::None);
  CHECK(t.x == 0.f);
  CHECK(t.w == 20.f);
  CHECK(t.h == 20.f);  // cut at the bottom edge (H = 120)
  CHECK(initTarget(RgbView{}, Box{0.f, 0.f, 10.f, 10.f}, &t) == InitError::NoColour);
  CHECK(initTarget(f.rgb, Box{}, &t) == InitError::EmptyBox);
  CHECK(initTarget(f.rgb, Box{W + 5.f, 0.f, 10.f, 10.f}, &t) == InitError::BoxOutsideImage);
  CHECK(initTarget(f.rgb, Box{W - 2.f, 0.f, 10.f, 10.f}, &t) == InitError::BoxTooSmall);
}

TEST_CASE("ConfigError: every preset is valid", "[core][config]") {
  for (int i = 0; i < kNumPresets; ++i) {
    const Preset p = static_cast<Preset>(i);
    INFO(presetName(p));
    CHECK(validate(presetConfig(p)) == ConfigError::None);
    CHECK(gTracker.configure(presetConfig(p), 1) == ConfigError::None);
  }
}

TEST_CASE("ConfigError: an invalid configuration is refused with its reason, not clamped",
          "[core][config]") {
  const TrackerConfig good = presetConfig(Preset::Best);
  struct Bad {
    void (*spoil)(TrackerConfig&);
    ConfigError why;
  };
  const Bad bad[] = {
      {[](TrackerConfig& c) { c.numParticles = 0; }, ConfigError::ParticlesOutOfRange},
      {[](TrackerConfig& c) { c.numParticles = kMaxParticles + 1; },
       ConfigError::ParticlesOutOfRange},
      {[](TrackerConfig& c) { c.numWeakClassifiers = 0; }, ConfigError::WeakClassifiersOutOfRange},
      {[](TrackerConfig& c) { c.numWeakClassifiers = 33; }, ConfigError::WeakClassifiersOutOfRange},
      {[](TrackerConfig& c) { c.numWeakClassifiers2d = -1; },
       ConfigError::WeakClassifiers2dOutOfRange},
      {[](TrackerConfig& c) { c.numWeakClassifiers2d = 33; },
       ConfigError::WeakClassifiers2dOutOfRange},
      {[](TrackerConfig& c) { c.lostAfter2d = -1; }, ConfigError::LostAfter2dNegative},
      {[](TrackerConfig& c) { c.useGray = c.useColour = c.useDepth = false; },
       ConfigError::NoFeatures},
      {[](TrackerConfig& c) { c.stateSpace = static_cast<StateSpace>(7); },
       ConfigError::UnknownStateSpace},
      {[](TrackerConfig& c) { c.sampling = static_cast<FeatureSampling>(7); },
       ConfigError::UnknownSampling},
  };
  REQUIRE(gTracker.configure(good, 1) == ConfigError::None);
  for (const Bad& b : bad) {
    TrackerConfig c = good;
    b.spoil(c);
    INFO(toString(b.why));
    CHECK(validate(c) == b.why);
    CHECK(gTracker.configure(c, 2) == b.why);
    // The tracker keeps the configuration it had.
    CHECK(gTracker.config().numParticles == good.numParticles);
    CHECK(gTracker.config().numWeakClassifiers == good.numWeakClassifiers);
    CHECK(gTracker.config().stateSpace == good.stateSpace);
    CHECK(std::string(toString(b.why)).size() > 10);
  }
  // The edges are valid: one particle, one weak classifier, the capacities.
  TrackerConfig edge = good;
  edge.numParticles = 1;
  edge.numWeakClassifiers = 1;
  CHECK(validate(edge) == ConfigError::None);
  edge.numParticles = kMaxParticles;
  edge.numWeakClassifiers = kMaxWeakClassifiers;
  edge.numWeakClassifiers2d = kMaxWeakClassifiers;
  CHECK(validate(edge) == ConfigError::None);
}
