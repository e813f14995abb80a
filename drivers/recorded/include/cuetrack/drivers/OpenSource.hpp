// The one way apps and the benchmark open a source of frames.
//
//   spec                        format
//   synth:<scene>[:frames]      SyntheticSource (scenes: see SyntheticSource.hpp)
//   <dir> with INDEX.txt        fakenect recording
//   <dir> with rgb/ + depth/    RGB-D sequence folder            (host build with OpenCV)
//   <dir> with img/             OTB folder                        (host build with OpenCV)
//   <file>.avi                  BoBoT video + <file>.gt.txt       (host build with OpenCV)
//   pan:RGB,DEPTH,...           a real RGB-D still, panned        (host build with OpenCV)
//   still:RGB,DEPTH,...:SCENE@u,v,gapMm  a scene in a real still  (host build with OpenCV)
//
// Without OpenCV (the board) only synth and fakenect open; the others fail with a line
// saying the format needs a host build with OpenCV.
#pragma once

#include <cstddef>
#include <memory>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

// nullptr on failure, with one line in err naming the path at fault.
std::unique_ptr<FrameSource> openFrameSource(const char* spec, const SourceOptions& opt, char* err,
                                             size_t errLen);
// True when this build reads the OpenCV formats.
bool frameSourcesHaveOpenCv();
// Help text listing the accepted specs (for --help).
const char* frameSourceHelp();

}  // namespace cuetrack
