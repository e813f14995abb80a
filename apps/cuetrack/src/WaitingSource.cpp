#include "WaitingSource.hpp"

#include <cstdio>
#include <cstring>

namespace cuetrack::app {

bool WaitingSource::tryOpen() {
  if (_inner) return true;
  ++_attempts;
  _lastTryUs = _clock.nowUs();
  char why[sizeof _why] = "";
  _inner = _open(_ctx, why, sizeof why);
  char line[sizeof _why + 64];
  if (_inner) {
    if (_waited) {
      std::snprintf(line, sizeof line, "%s: found after %d attempts; frames flow", _inner->name(),
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
  while (!_inner) {
    if (_attempts > 0) {
      _sleeper.sleepUs(kSliceUs);
      if (idle() || (_stopRequested && _stopRequested())) return ReadStatus::End;
      if (_clock.nowUs() - _lastTryUs < kRetryUs) continue;
    }
    tryOpen();
  }
  passIdleHookTo(*_inner);
  return _inner->next(out);
}

}  // namespace cuetrack::app
