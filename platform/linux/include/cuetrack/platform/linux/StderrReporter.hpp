// Reporter to stderr: "<prefix>: <line>\n" in one write.
#pragma once

#include "cuetrack/platform/Reporter.hpp"

namespace cuetrack::platform {

class StderrReporter final : public Reporter {
 public:
  explicit StderrReporter(const char* prefix) : _prefix(prefix) {}
  void report(const char* line) override;

 private:
  const char* _prefix;
};

}  // namespace cuetrack::platform
