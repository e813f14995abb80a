// CLOCK_MONOTONIC in microseconds: never jumps with NTP or date changes.
#pragma once

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/Sleeper.hpp"

namespace cuetrack::platform {

class MonotonicClock final : public Clock {
 public:
  uint64_t nowUs() const override;
};

// nanosleep on CLOCK_MONOTONIC; a signal (SIGINT) ends it early.
class MonotonicSleeper final : public Sleeper {
 public:
  void sleepUs(uint64_t us) override;
};

}  // namespace cuetrack::platform
