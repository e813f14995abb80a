#include "cuetrack/platform/linux/MonotonicClock.hpp"

#include <time.h>

namespace cuetrack::platform {

uint64_t MonotonicClock::nowUs() const {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<uint64_t>(ts.tv_sec) * 1000000u + static_cast<uint64_t>(ts.tv_nsec) / 1000u;
}

void MonotonicSleeper::sleepUs(uint64_t us) {
  timespec ts{};
  ts.tv_sec = static_cast<time_t>(us / 1000000u);
  ts.tv_nsec = static_cast<long>((us % 1000000u) * 1000u);
  clock_nanosleep(CLOCK_MONOTONIC, 0, &ts, nullptr);  // EINTR: the caller re-checks
}

}  // namespace cuetrack::platform
