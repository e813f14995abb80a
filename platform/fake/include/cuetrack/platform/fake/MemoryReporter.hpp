// Keeps the reported lines in memory so tests can assert on them.
#pragma once

#include <cstdio>
#include <cstring>

#include "cuetrack/platform/Reporter.hpp"

namespace cuetrack::platform {

class MemoryReporter final : public Reporter {
 public:
  static constexpr int kMaxLines = 64;
  void report(const char* line) override {
    if (_count < kMaxLines) std::snprintf(_lines[_count], sizeof _lines[0], "%s", line);
    ++_count;
  }
  int count() const { return _count; }
  const char* line(int i) const { return i < kMaxLines ? _lines[i] : ""; }
  // Number of lines containing `needle`.
  int countContaining(const char* needle) const {
    int n = 0;
    for (int i = 0; i < _count && i < kMaxLines; ++i)
      n += std::strstr(_lines[i], needle) != nullptr;
    return n;
  }

 private:
  char _lines[kMaxLines][256]{};
  int _count{0};
};

}  // namespace cuetrack::platform
