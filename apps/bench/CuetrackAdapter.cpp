#include <memory>

#include "TrackerAdapters.hpp"
#include "cuetrack/core/Tracker.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"

namespace cuetrack::bench {
namespace {

// The tracker is MiBs: one instance for the whole process, allocated at the first use
// (before any timing), then reconfigured for every run.
Tracker& sharedTracker() {
  static std::unique_ptr<Tracker> tracker = std::make_unique<Tracker>();
  return *tracker;
}

class CuetrackBench final : public BenchTracker {
 public:
  explicit CuetrackBench(Preset preset) : _preset(preset) {}

  bool init(const CachedFrame& f, const Box& box, uint64_t seed, std::string* err) override {
    Tracker& t = sharedTracker();
    t.configure(presetConfig(_preset), seed, &_clock);
    const InitError e = t.init(f.frame(), box);
    if (e == InitError::None) return true;
    *err = std::string("cannot run: init failed: ") + toString(e);
    return false;
  }

  Box update(const CachedFrame& f, double* stageUs) override {
    const TrackResult r = sharedTracker().update(f.frame());
    stageUs[0] = r.timesUs.features;
    stageUs[1] = r.timesUs.predict;
    stageUs[2] = r.timesUs.weigh;
    stageUs[3] = r.timesUs.learn;
    stageUs[4] = r.timesUs.total;
    // Lost (or idle): the tracker reports no target, scored as an empty box.
    return r.state == TrackState::Tracking ? r.box : Box{};
  }
  bool hasStages() const override { return true; }

 private:
  Preset _preset;
  platform::MonotonicClock _clock;
};

}  // namespace

std::unique_ptr<BenchTracker> makeCuetrackBench(const std::string& config, std::string* err) {
  Preset p;
  if (!parsePreset(config.c_str(), &p)) {
    *err = "unknown configuration '" + config + "' (use 1.1 ... 1.4, 2.1 ... 2.5 or best)";
    return nullptr;
  }
  return std::make_unique<CuetrackBench>(p);
}

}  // namespace cuetrack::bench
