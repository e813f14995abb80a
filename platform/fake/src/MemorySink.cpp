#include "cuetrack/platform/fake/MemorySink.hpp"

#include <cstdio>

namespace cuetrack::platform {

bool MemorySink::write(const ctp_track_t& track) {
  if (_failing) {
    std::snprintf(_error, sizeof _error, "memory: write failed (simulated)");
    return false;
  }
  if (_count >= kCapacity) {
    ++_overflowed;
    return true;
  }
  _tracks[_count++] = track;
  return true;
}

}  // namespace cuetrack::platform
