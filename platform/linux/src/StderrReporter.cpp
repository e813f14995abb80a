#include "cuetrack/platform/linux/StderrReporter.hpp"

#include <unistd.h>

#include <cstdio>

namespace cuetrack::platform {
namespace {

// One write per line: lines from concurrent writers do not interleave mid-line.
// False when the line did not go out whole.
bool writeLine(int fd, const char* prefix, const char* line) {
  char buf[640];
  int n = prefix ? std::snprintf(buf, sizeof buf, "%s: %s\n", prefix, line)
                 : std::snprintf(buf, sizeof buf, "%s\n", line);
  if (n < 0) return false;
  if (static_cast<size_t>(n) >= sizeof buf) {
    n = static_cast<int>(sizeof buf) - 1;
    buf[n - 1] = '\n';
  }
  // A line stays one line: control characters echoed from input (a newline in an
  // argument or a file name) are shown as '?'.
  for (int i = 0; i < n - 1; ++i)
    if (static_cast<unsigned char>(buf[i]) < 0x20 || buf[i] == 0x7f) buf[i] = '?';
  return ::write(fd, buf, static_cast<size_t>(n)) == n;
}

}  // namespace

void StderrReporter::report(const char* line) {
  writeLine(2, _prefix, line);
}

void LineReporter::report(const char* line) {
  if (!writeLine(_stream == StdStream::Out ? 1 : 2, nullptr, line)) _failed = true;
}

}  // namespace cuetrack::platform
