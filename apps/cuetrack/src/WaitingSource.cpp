#include "WaitingSource.hpp"

#include <cstdio>
#include <cstring>

namespace cuetrack::app {

bool WaitingSource::tryOpen() {
  if (inner()) return true;
  ++_attempts;
  _lastTryUs = _clock.nowUs();
  char why[sizeof _why] = "";
  setInner(_open(_ctx, why, sizeof why));
  char line[sizeof _why + 64];
  if (inner()) {
    if (_waited) {
      std::snprintf(line, sizeof line, "%s: found after %d attempts; frames flow", inner()->name(),
                    _attempts);
      _reporter.report(line);
    }
    return true;
  }
  if (std::strcmp(why, _why) != 0) {
    std::snprintf(_why, sizeof _why, "%s", why);
    std::snprintf(line, sizeof line, "%s; waiting for it (--wait-camera)", _why);
    _reporter.report(line);
  }
  _waited = true;
  return false;
}

ReadStatus WaitingSource::next(FrameSlot& out) {
  constexpr uint64_t kSliceUs = static_cast<uint64_t>(kIdleSliceMs) * 1000u;
  while (!inner()) {
    if (_attempts > 0) {
      _sleeper.sleepUs(kSliceUs);
      if (idle() || (_stopRequested && _stopRequested())) return ReadStatus::End;
      if (_clock.nowUs() - _lastTryUs < kRetryUs) continue;
    }
    tryOpen();
  }
  return forwardNext(out);
}

}  // namespace cuetrack::app
