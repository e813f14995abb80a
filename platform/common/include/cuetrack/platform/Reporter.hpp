// One-line human reports (errors, reconnects, status) from the app's parts; stderr
// on the board, memory in tests.
#pragma once

namespace cuetrack::platform {

class Reporter {
 public:
  virtual ~Reporter() = default;
  virtual void report(const char* line) = 0;  // one line, no trailing newline
};

}  // namespace cuetrack::platform
