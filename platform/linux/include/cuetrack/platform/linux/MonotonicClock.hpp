// CLOCK_MONOTONIC in microseconds: never jumps with NTP or date changes.
#pragma once

#include "cuetrack/core/Clock.hpp"

namespace cuetrack::platform {

class MonotonicClock final : public Clock {
 public:
  uint64_t nowUs() const override;
};

}  // namespace cuetrack::platform
