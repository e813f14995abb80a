// Text forms of a track message: the human line (stdout, listener) and CSV rows
// (--out FILE, cuetrack-listen --csv). Both come from the quantised wire message,
// so the app's file and the listener's CSV compare equal field for field.
#pragma once

#include <cstddef>

#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::platform {

// All return the length written (without the NUL), or 0 when cap is too small.
// Lines end with '\n'.
size_t formatTrackLine(const ctp_track_t& t, char* buf, size_t cap);
const char* trackCsvHeader();  // with '\n'
size_t formatTrackCsvRow(const ctp_track_t& t, char* buf, size_t cap);
size_t formatMessageLine(const ctp_message_t& m, char* buf, size_t cap);  // any device msg

// Quantises a tracker result into a wire message (seq left 0). previousState is the
// protocol state of the frame before, used to tell LOST (first frame) from SEARCHING.
ctp_track_t toTrackMessage(const TrackResult& r, uint64_t frameTimeUs, uint32_t procUs,
                           uint8_t previousState);

}  // namespace cuetrack::platform
