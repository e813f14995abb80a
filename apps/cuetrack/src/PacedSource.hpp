// --realtime: a recording or a synthetic scene played at its own frame rate, by its
// timestamps, as a camera would deliver it (otherwise frames come as fast as the tracker
// takes them). While it waits between frames it calls its caller's idle hook every
// FrameSource::kIdleSliceMs, like the live Kinect, so the serial link stays served.
#pragma once

#include "ForwardingSource.hpp"
#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/Sleeper.hpp"

namespace cuetrack::app {

class PacedSource final : public ForwardingSource {
 public:
  // stopRequested (may be null) is polled between slices too (SIGINT during a long gap).
  PacedSource(FrameSource& inner, const Clock& clock, platform::Sleeper& sleeper,
              bool (*stopRequested)() = nullptr)
      : ForwardingSource(&inner), _clock(clock), _sleeper(sleeper), _stopRequested(stopRequested) {}

  ReadStatus next(FrameSlot& out) override;

 private:
  const Clock& _clock;
  platform::Sleeper& _sleeper;
  bool (*_stopRequested)();
  bool _started = false;
  uint64_t _firstFrameUs = 0;  // the first frame's timestamp
  uint64_t _firstWallUs = 0;   // when it was handed out
};

}  // namespace cuetrack::app
