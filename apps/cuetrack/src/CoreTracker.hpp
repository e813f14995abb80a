// TrackerPort over the real cuetrack::Tracker (which the caller keeps in static storage).
#pragma once

#include "TrackerPort.hpp"
#include "cuetrack/core/tracker/Tracker.hpp"

namespace cuetrack::app {

class CoreTracker final : public TrackerPort {
 public:
  explicit CoreTracker(Tracker& tracker) : _tracker(tracker) {}
  bool configure(const char* preset, uint64_t seed, const Clock* clock) override;
  int init(const Frame& frame, const Box& box, const char** why) override;
  TrackResult update(const Frame& frame) override { return _tracker.update(frame); }
  void reset() override { _tracker.reset(); }

 private:
  Tracker& _tracker;
};

}  // namespace cuetrack::app
