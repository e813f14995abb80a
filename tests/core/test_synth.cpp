// End to end on the synthetic RGB-D scenes of drivers/synth (640x480, Kinect depth
// model): every preset tracks a plainly moving target; in 3D a target that a
// same-textured twin crosses at another depth is kept; no allocation in any run.
#include <catch2/catch.hpp>
#include <cstdlib>

#include "AllocCounter.hpp"
#include "cuetrack/core/Tracker.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;

namespace {
Tracker tracker;
FrameSlot slot;

struct Stats {
  int frames = 0, hits = 0;
  double overlapSum = 0;
  uint64_t allocations = 0;
  float hitRate() const {
    return frames ? static_cast<float>(hits) / static_cast<float>(frames) : 0.f;
  }
};

Stats runScene(const char* scene, Preset preset, uint64_t seed, int frames) {
  SceneSpec spec;
  REQUIRE(makeScene(scene, &spec));
  spec.frameCount = frames;
  static SyntheticSource* src = nullptr;
  // One source object reused (placement into static storage: no heap in the loop).
  alignas(SyntheticSource) static unsigned char storage[sizeof(SyntheticSource)];
  if (src != nullptr) src->~SyntheticSource();
  src = new (storage) SyntheticSource(spec, seed);
  Stats s;
  tracker.configure(presetConfig(preset), seed);
  REQUIRE(src->next(slot) == ReadStatus::Ok);
  const test::AllocScope scope;
  REQUIRE(tracker.init(slot.frame(), slot.groundTruth) == InitError::None);
  while (src->next(slot) == ReadStatus::Ok) {
    const TrackResult r = tracker.update(slot.frame());
    const float o = overlap(r.box, slot.groundTruth);
    s.overlapSum += o;
    s.hits += o > 1.f / 3.f ? 1 : 0;
    ++s.frames;
  }
  s.allocations = scope.allocations();
  return s;
}
}  // namespace

bool emulated() {
  return std::getenv("CUETRACK_EMULATED") != nullptr;  // under qemu: fewer, shorter runs
}

TEST_CASE("every preset tracks the synthetic moving target", "[core][e2e]") {
  for (int i = 0; i < kNumPresets; ++i) {
    const Preset p = static_cast<Preset>(i);
    if (emulated() && p != Preset::Test1_1 && p != Preset::Best) continue;
    const int frames = emulated() ? 10 : 90;
    const Stats s = runScene("moving", p, 11, frames);
    INFO("preset " << presetName(p) << ": hit rate " << s.hitRate() << ", mean overlap "
                   << s.overlapSum / s.frames);
    REQUIRE(s.frames == frames - 1);
    REQUIRE(s.hitRate() >= 0.98f);
    REQUIRE(s.allocations == 0);
  }
}

TEST_CASE("3D keeps the target when a same-textured twin crosses it", "[core][e2e]") {
  if (emulated()) {
    WARN("twin-crossing skipped under emulation (150 frames at 640x480 take too long in qemu)");
    return;
  }
  for (Preset p : {Preset::Test2_1, Preset::Best}) {
    const Stats s = runScene("twin-crossing", p, 5, 150);
    INFO("preset " << presetName(p) << ": hit rate " << s.hitRate() << ", mean overlap "
                   << s.overlapSum / s.frames);
    REQUIRE(s.hitRate() >= 0.95f);
    REQUIRE(s.allocations == 0);
  }
  // For the record (the paper's point): the 2D grayscale preset may lose it.
  const Stats g = runScene("twin-crossing", Preset::Test2_5, 5, 150);
  WARN("preset 2.5 on twin-crossing: hit rate " << g.hitRate());
}
