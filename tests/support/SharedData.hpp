// Where the shared real data lives: $CUETRACK_SHARED_DIR, else the compile-time default.
// Tests that need it call CUETRACK_SKIP (Skip.hpp) when it is absent: ctest reports them
// as skipped. CUETRACK_SHARED_DIR=/nonexistent ctest hides the data.
#pragma once

#include <sys/stat.h>

#include <cstdlib>
#include <string>

#include "TestPaths.hpp"

namespace cuetrack::test {

inline std::string sharedDataDir() {
  const char* env = std::getenv("CUETRACK_SHARED_DIR");
  std::string base = env && *env ? env : CUETRACK_SHARED_DIR;
  return base + "/data";
}

inline bool pathExists(const std::string& p) {
  struct stat st {};
  return ::stat(p.c_str(), &st) == 0;
}

}  // namespace cuetrack::test
