// --video FILE.avi: every frame with its track drawn (Motion JPEG), written on the caller's
// thread, so it costs the tracker's loop an encode per frame (a few ms).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "ViewTrack.hpp"
#include "cuetrack/core/base/Frame.hpp"

namespace cuetrack::app {

class VideoOut {
 public:
  VideoOut();
  ~VideoOut();
  VideoOut(const VideoOut&) = delete;
  VideoOut& operator=(const VideoOut&) = delete;

  bool open(const char* path, double fps, char* err, size_t errLen);  // fps 0: 30
  bool write(const Frame& frame, const ViewTrack& track, char* err, size_t errLen);
  bool close(char* err, size_t errLen);  // false: the file is missing or empty
  uint32_t frames() const { return _frames; }

 private:
  struct Impl;  // OpenCV's writer: this header stays free of OpenCV (the board's stub)
  std::unique_ptr<Impl> _impl;
  uint32_t _frames = 0;
};

}  // namespace cuetrack::app
