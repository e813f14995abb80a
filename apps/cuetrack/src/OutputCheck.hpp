// Before anything is opened: no output of cuetrack (--out, --video, --snapshot) may
// overwrite an input (the --source file or folder, a video's ground truth, --gt, the stills of a
// pan:/still: source, the --mavlink-key) or another output (apps/common OutputGuard). False
// with one line in err naming both paths.
#pragma once

#include <cstddef>

#include "Options.hpp"

namespace cuetrack::app {

bool checkOutputs(const AppOptions& opt, char* err, size_t errLen);

}  // namespace cuetrack::app
