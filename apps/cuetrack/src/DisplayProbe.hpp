// Whether this build and this session can show anything: asked before any frame is read,
// so a missing display is one line at start, not an abort from inside Qt.
#pragma once

#include <cstddef>

namespace cuetrack::app {

// This build has OpenCV's highgui/videoio (--snapshot, --video, --show, --select).
bool viewBuilt();

// This build can open windows (OpenCV highgui) and $DISPLAY names a display; else false
// and one line in err naming what is missing.
bool displayAvailable(char* err, size_t errLen);

}  // namespace cuetrack::app
