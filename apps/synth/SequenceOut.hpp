// Writing a sequence in one of the recorded formats, shared by cuetrack-synth and
// cuetrack-convert. Formats: "fakenect" (everywhere); with OpenCV also "rgbd" (RGB-D
// folder), "otb" (OTB folder, JPEG, colour only) and "avi" (BoBoT-style MJPG video +
// .gt.txt; `dir` is then the .avi path).
#pragma once

#include <cstddef>
#include <memory>

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack {

class SequenceOut {
 public:
  virtual ~SequenceOut() = default;
  virtual bool write(const FrameSlot& frame) = 0;
  virtual bool close() = 0;
  virtual const char* error() const = 0;
};

// nullptr with a line in err for an unknown format or an output that cannot be created.
// fps: the source's frame rate (FrameSource::nominalFps), the avi container's rate; 0 =
// unknown, then 30 (the Kinect's).
std::unique_ptr<SequenceOut> openSequenceOut(const char* format, const char* dir, const char* name,
                                             double fps, char* err, size_t errLen);

// Copies every frame of src into out; returns frames written, -1 on error (line in err).
int copySequence(FrameSource& src, SequenceOut& out, FrameSlot& slot, char* err, size_t errLen);

}  // namespace cuetrack
