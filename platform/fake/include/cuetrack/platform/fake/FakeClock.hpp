// A clock the test sets by hand: time moves only when the test says so.
#pragma once

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/Sleeper.hpp"

namespace cuetrack::platform {

class FakeClock final : public Clock {
 public:
  explicit FakeClock(uint64_t startUs = 0) : _nowUs(startUs) {}
  uint64_t nowUs() const override { return _nowUs; }
  void setUs(uint64_t us) { _nowUs = us; }
  void advanceUs(uint64_t us) { _nowUs += us; }

 private:
  uint64_t _nowUs;
};

// Sleeping moves the fake clock: paced code runs at once and the test reads the time.
class FakeSleeper final : public Sleeper {
 public:
  explicit FakeSleeper(FakeClock& clock) : _clock(clock) {}
  void sleepUs(uint64_t us) override {
    _clock.advanceUs(us);
    sleptUs += us;
    ++calls;
  }
  uint64_t sleptUs = 0;
  int calls = 0;

 private:
  FakeClock& _clock;
};

}  // namespace cuetrack::platform
