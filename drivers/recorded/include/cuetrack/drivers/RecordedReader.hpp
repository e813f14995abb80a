// What every recorded-sequence reader shares (fakenect, BoBoT video, RGB-D and OTB
// folders): frames come in order, one index each; a frame that cannot be read stops the
// reader with one line naming it, or with SourceOptions::skipBadFrames is skipped and
// counted; SourceOptions::maxFrames ends it early; each frame returned is stamped with
// its index, time, intrinsics and ground-truth box. A reader says only how to read frame
// i and when it was taken. No decoding library here: the board builds it.
#pragma once

#include <cstdint>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/GroundTruth.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

// The Kinect v1's intrinsics scaled to a w x h image: for recordings that carry none.
CameraIntrinsics kinectIntrinsicsScaled(int widthPx, int heightPx);

class RecordedReader : public FrameSource {
 public:
  ReadStatus next(FrameSlot& out) final;
  const char* error() const final { return _error; }
  const char* name() const final { return _name.c_str(); }
  int skippedFrames() const final { return _skipped; }
  const char* warning() const final { return _warning; }

 protected:
  enum class FrameRead : uint8_t {
    Ok,     // out holds frame i's colour (and depth, hasDepth)
    Bad,    // frame i is unreadable (error() says why): skipped with skipBadFrames
    End,    // there is no frame i
    Error,  // the reader cannot go on (error() says why)
  };
  virtual FrameRead readFrame(int i, FrameSlot& out) = 0;
  virtual uint64_t frameTimeUs(int i) const = 0;
  // A recording with intrinsics of its own overrides this.
  virtual CameraIntrinsics frameIntrinsics(int widthPx, int heightPx) const {
    return kinectIntrinsicsScaled(widthPx, heightPx);
  }

  // Back to frame 0 with no error and no ground truth: the start of every open().
  void restart(const SourceOptions& opt);
  // The ground truth of a recording of `frames` frames: SourceOptions::gtPath, else
  // besidePath when it exists (none is fine). One box per frame, or none for the last
  // (BoBoT's convention); frames <= 0 (unknown) skips that check. framesNoun names the
  // frames in the error ("frames", "video frames").
  bool loadGroundTruth(const std::string& besidePath, GtFormat format, int frames,
                       const char* framesNoun);

  std::string _name;
  SourceOptions _opt{};
  GroundTruth _gt;
  int _next = 0;     // index of the next frame to read
  int _emitted = 0;  // frames returned
  int _skipped = 0;  // frames skipped as unreadable
  // [px] of the first frame returned, in the source's own pixels (before any scaling
  // down, FrameScale.hpp): every frame must match.
  int _width = 0, _height = 0;
  char _error[768] = "";
  char _warning[768] = "";
};

}  // namespace cuetrack
