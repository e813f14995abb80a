#include "cuetrack/platform/linux/StderrReporter.hpp"

#include <unistd.h>

#include <cstdio>

namespace cuetrack::platform {

void StderrReporter::report(const char* line) {
  char buf[640];
  int n = std::snprintf(buf, sizeof buf, "%s: %s\n", _prefix, line);
  if (n < 0) return;
  if (static_cast<size_t>(n) >= sizeof buf) {
    n = static_cast<int>(sizeof buf) - 1;
    buf[n - 1] = '\n';
  }
  // One write: lines from the app and a concurrent logger do not interleave mid-line.
  ssize_t ignored = ::write(2, buf, static_cast<size_t>(n));
  (void)ignored;
}

}  // namespace cuetrack::platform
