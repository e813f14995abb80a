// Where track messages go besides the serial link: a file, stdout, memory in tests.
#pragma once

#include "cuetrack_proto.h"

namespace cuetrack::platform {

class TrackSink {
 public:
  virtual ~TrackSink() = default;
  // False when the message could not be written (disk full, pipe closed...);
  // error() then has one line naming the file.
  virtual bool write(const ctp_track_t& track) = 0;
  virtual const char* error() const = 0;
  virtual const char* name() const = 0;
};

}  // namespace cuetrack::platform
