// Where a doc the tools name (docs/first-hour.md) is for this program: installed beside
// it (share/doc/cuetrack/docs/, as `cmake --install` and the .deb put the docs), or in the
// clone it was built in (build/<preset>/bin/); else the clone-relative name as given.
#pragma once

#include <string>

namespace cuetrack::app {

// exePath: the program's own path (its bin/ folder is what counts); rel: "docs/NAME.md".
std::string findDoc(const std::string& exePath, const char* rel);

// The same for the running program (/proc/self/exe).
std::string findDoc(const char* rel);

}  // namespace cuetrack::app
