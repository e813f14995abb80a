// Opens the frame source named on the command line. Every source lives in static
// storage inside Sources.cpp (they are MiBs); at most one is opened per process.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::app {

// spec: nullptr (Kinect when present, else a V4L2 camera when one opens, else
// synth:<default scene>), "kinect", "camera[:N|:/dev/videoN]",
// "synth" / "synth:SCENE", or a recording path. A synthetic scene runs for `frames`
// frames when that is > 0 (the scene's own length otherwise). skipBadFrames: a recording
// skips damaged frames (counted, skippedFrames()) instead of failing. nullptr + one line
// in err on failure.
// gtPath: a recording's ground truth under another name (nullptr: its own);
// gtOptional: the target comes from elsewhere, so ground truth beside the recording that
// does not fit is left out with the source's warning() instead of failing it.
FrameSource* openSource(const char* spec, uint64_t seed, int frames, char* err, size_t errLen,
                        bool skipBadFrames = false, const char* gtPath = nullptr,
                        bool gtOptional = false);

// After openSource(nullptr, ...): which source the default chose and why, one phrase, e.g.
// "synth:moving, a generated scene (no Kinect found; --source to choose)". Else spec.
void describeSourceChoice(const char* spec, char* out, size_t outLen);

// This build has the Kinect driver (libfreenect): a Kinect can be opened, now or later.
bool kinectSupported();

// Where the ground truth of source `spec` comes from, for messages: the file its reader
// takes (drivers/recorded/.../OpenSource.hpp), e.g. "rec/groundtruth.txt", or the
// spec itself for generated sources ("synth:moving ground truth").
// With gtPath (--gt), that file.
void describeGroundTruth(const char* spec, char* out, size_t outLen, const char* gtPath = nullptr);

// Frames lost so far: unreadable frames skipped, plus for the Kinect the frames it
// dropped because the tracker was slower than the camera.
uint64_t droppedFrames(const FrameSource& source);

}  // namespace cuetrack::app
