// The programs of this build that a test runs (cuetrack, cuetrack-listen...): found when the
// test runs, beside the test's own executable, as a build puts every program in its bin/.
// Not compiled in: no folder of this clone is then on a test's command line, and the compiler
// cache serves a clone in another folder (as TestPaths.hpp). tests/apps/CMakeLists.txt makes
// each test depend on the programs it runs.
#pragma once

#include <unistd.h>

#include <climits>
#include <cstdio>
#include <map>
#include <string>

namespace cuetrack::test {

// The absolute path of this build's program `name`; the pointer stays valid (one string a
// name, kept for the run).
inline const char* programPath(const char* name) {
  static std::map<std::string, std::string> paths;
  auto found = paths.find(name);
  if (found != paths.end()) return found->second.c_str();
  char self[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", self, sizeof self - 1);
  std::string dir = n > 0 ? std::string(self, static_cast<size_t>(n)) : std::string("./x");
  dir.erase(dir.find_last_of('/') + 1);
  if (n <= 0) std::fprintf(stderr, "programPath: /proc/self/exe unreadable, looking in ./\n");
  return paths.emplace(name, dir + name).first->second.c_str();
}

}  // namespace cuetrack::test

#define CUETRACK_APP_BIN ::cuetrack::test::programPath("cuetrack")
#define CUETRACK_LISTEN_BIN ::cuetrack::test::programPath("cuetrack-listen")
#define CUETRACK_SYNTH_BIN ::cuetrack::test::programPath("cuetrack-synth")
#define CUETRACK_TRACKSPEED_BIN ::cuetrack::test::programPath("cuetrack-trackspeed")
#define CUETRACK_CONVERT_BIN ::cuetrack::test::programPath("cuetrack-convert")
