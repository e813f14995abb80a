// --wait-camera: a camera that is not plugged in yet is waited for, not an error. A robot
// often boots before the Kinect has power; with this the flight controller still hears
// from the board (HEARTBEATs flagged no-camera) and can already send its START.
// Until its opener succeeds, next() looks again every kRetryUs and calls its caller's
// idle hook every FrameSource::kIdleSliceMs meanwhile, like the Kinect during a stall;
// then it is its camera's source, unchanged. An attempt itself is not sliced: a missing
// Kinect is known in milliseconds, but a camera that answers slowly delays the
// heartbeats by as long as its open() takes.
#pragma once

#include <cstddef>

#include "ForwardingSource.hpp"
#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/Sleeper.hpp"

namespace cuetrack::app {

class WaitingSource final : public ForwardingSource {
 public:
  // Opens the camera, or returns nullptr with one line in err (e.g. "no Kinect found").
  using Opener = FrameSource* (*)(void* ctx, char* err, size_t errLen);
  static constexpr uint64_t kRetryUs = 1000000;

  // stopRequested (may be null) is polled between slices too (SIGINT while waiting).
  WaitingSource(Opener open, void* ctx, const Clock& clock, platform::Sleeper& sleeper,
                platform::Reporter& reporter, bool (*stopRequested)() = nullptr)
      : ForwardingSource(nullptr),
        _open(open),
        _ctx(ctx),
        _clock(clock),
        _sleeper(sleeper),
        _reporter(reporter),
        _stopRequested(stopRequested) {}

  // One attempt now. On failure, reports the reason and that it waits (once per
  // distinct reason: plugged in but not permitted reads differently from absent).
  bool tryOpen();

  ReadStatus next(FrameSlot& out) override;
  // Until the camera is there: why not, "camera", and awaiting it; then the camera's.
  const char* error() const override { return inner() ? ForwardingSource::error() : _why; }
  const char* name() const override { return inner() ? ForwardingSource::name() : "camera"; }
  bool awaitingDevice() const override { return inner() == nullptr; }

 private:
  Opener _open;
  void* _ctx;
  const Clock& _clock;
  platform::Sleeper& _sleeper;
  platform::Reporter& _reporter;
  bool (*_stopRequested)();
  int _attempts = 0;
  bool _waited = false;  // a failure was reported: report the camera's arrival too
  uint64_t _lastTryUs = 0;
  char _why[256] = "";
};

}  // namespace cuetrack::app
