// --select: the user drags the target's box on the first frame.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

enum class PickResult : uint8_t {
  Picked,       // *out holds the box
  Cancelled,    // c, Esc, Enter on no box, or the window closed: err says so
  Interrupted,  // stop() said so (SIGINT, SIGTERM, SIGHUP): the tool stops cleanly
};

// Shows frame and lets the user drag a box (Enter/space accepts, c or Esc cancels),
// polling stop() between events, so a signal is never ignored while the picker is open.
PickResult pickBox(const Frame& frame, bool (*stop)(), Box* out, char* err, size_t errLen);

}  // namespace cuetrack::app
