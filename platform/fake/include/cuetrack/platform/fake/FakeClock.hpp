// A clock the test sets by hand: time moves only when the test says so.
#pragma once

#include "cuetrack/core/Clock.hpp"

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

}  // namespace cuetrack::platform
