// The one way apps and the benchmark open a source of frames.
//
//   spec                        format
//   synth:<scene>[:frames]      SyntheticSource (scenes: see SyntheticSource.hpp)
//   <dir> with INDEX.txt        fakenect recording
//   <dir> with rgb/ + depth/    RGB-D sequence folder            (host build with OpenCV)
//   <dir> with img/             OTB folder                        (host build with OpenCV)
//   <dir> of images             image folder (+ groundtruth_rect.txt) (host, OpenCV)
//   <file>.avi/.mp4/.mkv/...    a video + <file>.gt.txt (BoBoT) or <file>.txt (OTB),
//                               MediaFiles.hpp                    (host build with OpenCV)
//   camera[:N|:/dev/videoN]     a V4L2 camera, CameraSource.hpp   (host build with OpenCV)
//   pan:RGB,DEPTH,...           a real RGB-D still, panned        (host build with OpenCV)
//   still:RGB,DEPTH,...:SCENE@u,v,gapMm  a scene in a real still  (host build with OpenCV)
//
// Without OpenCV (the board) only synth and fakenect open; the others fail with a line
// saying the format needs a host build with OpenCV. Videos, cameras and colour-only
// image folders of any size are scaled down to the working size (FrameSlot::scale).
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
// "camera", "camera:N" or "camera:/dev/..." (CameraSource.hpp).
bool isCameraSpec(const char* spec);
// The first V4L2 camera that opens (/dev/video0..9), for the default source; false when
// there is none or this build has no OpenCV.
bool findDefaultCamera(char* device, size_t deviceLen);
// Help text listing the accepted specs (for --help).
const char* frameSourceHelp();

}  // namespace cuetrack
