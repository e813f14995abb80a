#include "PacedSource.hpp"

namespace cuetrack::app {

ReadStatus PacedSource::next(FrameSlot& out) {
  const ReadStatus st = forwardNext(out);
  if (st != ReadStatus::Ok) return st;
  const uint64_t nowUs = _clock.nowUs();
  // The first frame sets the schedule; a timestamp going back (a looped recording) too.
  if (!_started || out.timeUs < _firstFrameUs) {
    _started = true;
    _firstFrameUs = out.timeUs;
    _firstWallUs = nowUs;
    return ReadStatus::Ok;
  }
  // Due by the recording's own clock. A tracker slower than the recording never waits:
  // frames then come late, none is skipped (a recording is for seeing every frame).
  const uint64_t dueUs = _firstWallUs + (out.timeUs - _firstFrameUs);
  constexpr uint64_t kSliceUs = static_cast<uint64_t>(kIdleSliceMs) * 1000u;
  for (uint64_t t = nowUs; t < dueUs; t = _clock.nowUs()) {
    const uint64_t leftUs = dueUs - t;
    _sleeper.sleepUs(leftUs < kSliceUs ? leftUs : kSliceUs);
    if (idle() || (_stopRequested && _stopRequested())) return ReadStatus::End;
  }
  return ReadStatus::Ok;
}

}  // namespace cuetrack::app
