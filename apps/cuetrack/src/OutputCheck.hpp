// Before anything is opened: no output of cuetrack (--out, --video, --snapshot) may
// overwrite an input (the --source file or folder, a video's ground truth, the stills of a
// pan:/still: source) or another output. False with one line in err naming both paths.
#pragma once

#include <cstddef>

#include "Options.hpp"

namespace cuetrack::app {

bool checkOutputs(const AppOptions& opt, char* err, size_t errLen);

}  // namespace cuetrack::app
