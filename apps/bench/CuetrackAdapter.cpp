#include <memory>

#include "TrackerAdapters.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"

namespace cuetrack::bench {
namespace {

// The tracker is MiBs: one instance for the whole process, allocated at the first use
// (before any timing), then reconfigured for every run.
Tracker& sharedTracker() {
  static std::unique_ptr<Tracker> tracker = std::make_unique<Tracker>();
  return *tracker;
}

// Ablations of the beyond-the-paper switches: "<preset>-<switch off>", e.g.
// best-nolost (no lost detection / re-acquisition), best-fixedsize (fixed cylinder),
// best-nofastmotion (no jumping particles, no coasting over dropped frames),
// best-nocorrelation (no template cue), best-noocclusion (learns covered frames too),
// best-template (the gray template as the correlation cue, in 2D and 3D, not the correlation
// filter), 1.1-centrednegatives (2D near negatives centred on the estimate),
// best-nofilterlead (2D: the particles and classifier with the plain filter as their cue,
// not the background-aware filter alone).
bool parseAblation(const std::string& name, TrackerConfig* out) {
  struct Off {
    const char* suffix;
    bool TrackerConfig::*flag;
  };
  static const Off kOffs[] = {{"-nolost", &TrackerConfig::lostDetection},
                              {"-fixedsize", &TrackerConfig::adaptCylinderSize},
                              {"-nofastmotion", &TrackerConfig::fastMotion},
                              {"-nocorrelation", &TrackerConfig::correlationCue},
                              {"-template", &TrackerConfig::correlationFilter},
                              {"-noocclusion", &TrackerConfig::occlusionGate},
                              {"-centrednegatives", &TrackerConfig::anchoredNegatives2d},
                              {"-nofilterlead", &TrackerConfig::filterLeads2d}};
  for (const Off& o : kOffs) {
    const std::string suffix(o.suffix);
    if (name.size() <= suffix.size() ||
        name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
      continue;
    Preset p;
    if (!parsePreset(name.substr(0, name.size() - suffix.size()).c_str(), &p)) return false;
    *out = presetConfig(p);
    out->*(o.flag) = false;
    return true;
  }
  return false;
}

class CuetrackBench final : public BenchTracker {
 public:
  explicit CuetrackBench(const TrackerConfig& config) : _config(config) {}

  bool init(const CachedFrame& f, const Box& box, uint64_t seed, std::string* err) override {
    Tracker& t = sharedTracker();
    if (const ConfigError c = t.configure(_config, seed, &_clock); c != ConfigError::None) {
      *err = std::string("cannot run: configuration refused: ") + toString(c);
      return false;
    }
    const InitError e = t.init(f.frame(), box);
    if (e == InitError::None) return true;
    *err = std::string("cannot run: init failed: ") + toString(e);
    return false;
  }

  Box update(const CachedFrame& f, double* stageUs) override {
    const TrackResult r = sharedTracker().update(f.frame());
    _hasPosition = r.state == TrackState::Tracking && r.hasPosition3d;
    for (int a = 0; a < 3; ++a) _positionMm[a] = r.positionMm[a];
    _hidden = r.occluded;
    stageUs[0] = r.timesUs.features;
    stageUs[1] = r.timesUs.predict;
    stageUs[2] = r.timesUs.weigh;
    stageUs[3] = r.timesUs.learn;
    stageUs[4] = r.timesUs.total;
    // Lost (or idle): the tracker reports no target, scored as an empty box. Occluded:
    // a box where the target was last seen, and no claim that it is visible.
    return r.state == TrackState::Tracking ? r.box : Box{};
  }
  bool hasStages() const override { return true; }
  bool lastHidden() const override { return _hidden; }
  bool lastPositionMm(float out[3]) const override {
    for (int a = 0; a < 3; ++a) out[a] = _positionMm[a];
    return _hasPosition;
  }

 private:
  TrackerConfig _config;
  bool _hasPosition = false;
  bool _hidden = false;
  float _positionMm[3] = {0.f, 0.f, 0.f};
  platform::MonotonicClock _clock;
};

}  // namespace

bool isCuetrackConfig(const std::string& config) {
  Preset p;
  TrackerConfig c;
  return parsePreset(config.c_str(), &p) || parseAblation(config, &c);
}

std::unique_ptr<BenchTracker> makeCuetrackBench(const std::string& config, std::string* err) {
  Preset p;
  TrackerConfig c;
  if (parsePreset(config.c_str(), &p)) {
    c = presetConfig(p);
  } else if (!parseAblation(config, &c)) {
    *err = "unknown configuration '" + config +
           "' (use 1.1 ... 1.4, 2.1 ... 2.5, dcf or best, or an ablation such as best-nolost, "
           "best-fixedsize)";
    return nullptr;
  }
  return std::make_unique<CuetrackBench>(c);
}

}  // namespace cuetrack::bench
