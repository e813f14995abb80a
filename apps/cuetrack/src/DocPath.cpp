#include "DocPath.hpp"

#include <unistd.h>
#include <climits>
#include <cstdlib>

namespace cuetrack::app {

std::string findDoc(const std::string& exePath, const char* rel) {
  const size_t slash = exePath.rfind('/');
  if (slash == std::string::npos) return rel;
  const std::string bin = exePath.substr(0, slash);
  // Installed (PREFIX/bin, PREFIX/share/doc/cuetrack), then built (CLONE/build/PRESET/bin).
  for (const char* up : {"/../share/doc/cuetrack/", "/../../../"}) {
    char real[PATH_MAX];
    if (realpath((bin + up + rel).c_str(), real) != nullptr) return real;
  }
  return rel;
}

std::string findDoc(const char* rel) {
  char exe[PATH_MAX];
  const ssize_t n = readlink("/proc/self/exe", exe, sizeof exe - 1);
  if (n <= 0) return rel;
  exe[n] = '\0';
  return findDoc(std::string(exe, static_cast<size_t>(n)), rel);
}

}  // namespace cuetrack::app
