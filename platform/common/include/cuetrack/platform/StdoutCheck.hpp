// What a tool printed with stdio reached its stdout, or the tool says so and fails: a
// full disk or /dev/full makes printf fail quietly, and exit(0) would then claim success.
#pragma once

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cuetrack::platform {

// Flushes stdout. False, with "PROGRAM: stdout: write failed: REASON" on stderr, when
// this or an earlier write to it failed.
inline bool stdoutWritten(const char* program) {
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  if (flushed && !std::ferror(stdout)) return true;
  std::fprintf(stderr, "%s: stdout: write failed: %s\n", program,
               errno ? std::strerror(errno) : "error on an earlier write");
  return false;
}

}  // namespace cuetrack::platform
