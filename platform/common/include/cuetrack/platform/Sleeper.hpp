// Waiting for a while, behind an interface: pacing code sleeps through it, and its tests
// hand it a fake that moves a FakeClock instead of the wall clock.
#pragma once

#include <cstdint>

namespace cuetrack::platform {

class Sleeper {
 public:
  virtual ~Sleeper() = default;
  // Returns after about `us` microseconds, or earlier on a signal (callers re-check).
  virtual void sleepUs(uint64_t us) = 0;
};

}  // namespace cuetrack::platform
