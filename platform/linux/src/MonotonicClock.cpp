#include "cuetrack/platform/linux/MonotonicClock.hpp"

#include <time.h>

namespace cuetrack::platform {

uint64_t MonotonicClock::nowUs() const {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000000u + static_cast<uint64_t>(ts.tv_nsec) / 1000u;
}

}  // namespace cuetrack::platform
