// A sequence decoded once into memory, so every tracker sees the very same frames and
// decoding never enters the timings; and the ways the bench cuts it (--stride,
// --drop-frames, --from/--to/--reverse).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::bench {

// One decoded frame, stored compactly (a FrameSlot is 1.5 MiB whatever the size).
struct CachedFrame {
  int index = 0;
  int width = 0, height = 0;  // [px] of rgb
  std::vector<Rgb8> rgb;
  std::vector<uint16_t> depthMm;  // empty when the source has no depth
  uint64_t timeUs = 0;
  CameraIntrinsics intrinsics{};
  bool hasGroundTruth = false;
  Box groundTruth{};
  bool hasTruthMm = false;  // the target's true 3D centre is known (synthetic scenes)
  float truthCentreMm[3] = {0.f, 0.f, 0.f};
  cv::Mat bgr;  // the same pixels for the OpenCV peers, converted once, outside the timings

  bool hasColour() const { return width > 0 && height > 0 && !rgb.empty(); }
  Frame frame() const;
};

struct Sequence {
  std::string name;
  std::string gtHeader;  // first line of the ground-truth file, for BoBoT result files
  std::vector<CachedFrame> frames;
  int skippedFrames = 0;
  int droppedFrames = 0;  // by thinSequence
  size_t bytes = 0;
};

// Decodes up to `maxFrames` (<= 0: all) frames. False with one line in *err when the
// source fails or the frames would exceed `maxBytes` of memory.
bool loadSequence(FrameSource& source, int maxFrames, size_t maxBytes, Sequence* seq,
                  std::string* err);

// A slower or lossier camera, from the same recording: after the first ground-truth frame
// (where trackers start) keeps every stride-th frame, and of those drops dropPct percent
// at random (the same frames for every tracker and run: a hash of seed and frame index).
// The kept frames keep their timestamps, so a tracker sees the gaps; dropped frames are
// neither tracked nor scored.
void thinSequence(Sequence* seq, int stride, int dropPct, uint64_t seed);

// Another start and direction from the same recording (OTB's temporal robustness
// protocol, and a target that moves the other way): keeps the frames whose index lies in
// [fromIndex, toIndex] (< 0: no bound), then, with `reverse`, plays them backwards, so
// the track begins at the last ground-truth box. Reversed timestamps are mirrored
// (t' = tMin + tMax - t) so they still increase with the same gaps; frame indices stay
// the recording's. The name gets ".fromF", ".toT", ".rev" so tables and output
// files say what was run (also on failure). False with one line in *err when no frame
// is left.
bool sliceSequence(Sequence* seq, int fromIndex, int toIndex, bool reverse, std::string* err);

}  // namespace cuetrack::bench
