// The end-of-run summary: how many frames, how fast, how much of it tracked, how sure,
// and (when the source has ground truth) how well the box overlapped the true one.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::app {

class RunSummary {
 public:
  // One frame as sent out; gt: the true box when the source has one for this frame.
  void add(const ctp_track_t& msg, const Box* gt);
  // "N frames in S s (F fps, M ms/frame tracking), tracked T/N (P%), mean confidence C
  //  [, ground-truth mean overlap O over G frames]". wallUs: the run's duration.
  void format(uint64_t wallUs, char* out, size_t outLen) const;

  uint32_t frames() const { return _frames; }
  uint32_t tracked() const { return _tracked; }
  uint32_t idle() const { return _idle; }
  double meanOverlap() const { return _gtFrames ? _overlapSum / _gtFrames : 0.0; }

 private:
  uint32_t _frames = 0;
  uint32_t _tracked = 0;        // state tracking
  uint32_t _idle = 0;           // no target yet
  double _confidenceSum = 0.0;  // over tracked frames
  uint64_t _procUsSum = 0;
  uint32_t _gtFrames = 0;  // frames with a visible true box, after the target was given
  double _overlapSum = 0.0;
};

}  // namespace cuetrack::app
