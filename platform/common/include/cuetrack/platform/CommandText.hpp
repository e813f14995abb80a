// The text form of inbound commands, as typed on cuetrack-listen's command line:
//   start:X,Y,W,H   reset   stop   rate:HZ
#pragma once

#include <cstddef>

#include "cuetrack_proto.h"

namespace cuetrack::platform {

// Fills *out with the command and the given id. Returns false with one line in err
// for malformed text.
bool parseCommandText(const char* text, uint16_t id, ctp_command_t* out, char* err, size_t errLen);
size_t formatCommandText(const ctp_command_t& c, char* buf, size_t cap);

}  // namespace cuetrack::platform
