// The core's only view of time: an interface that platform/ implements
// (monotonic clock on Linux, a settable fake in tests). Used for per-stage timings.
#pragma once

#include <cstdint>

namespace cuetrack {

class Clock {
 public:
  virtual ~Clock() = default;
  virtual uint64_t nowUs() const = 0;  // monotonic [us]
};

}  // namespace cuetrack
