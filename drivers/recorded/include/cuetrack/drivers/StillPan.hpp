// A real RGB-D still panned (host only, cuetrack_recorded_cv): each frame is a crop of
// the still whose offset sweeps sinusoidally (a camera panning and tilting by a few
// degrees: at these angles the image shifts, the depth of every point stays), with fresh
// colour noise (sigma 2 levels) per frame and the still's own depth. The ground truth is
// the given box, shifted with the crop. Spec (openFrameSource, parsed by
// rec::parsePanSpec): pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames]
//   RGB, DEPTH   colour image and 16-bit depth image (PNG or PGM), registered
//   x,y,w,h      the target's box in the still [px]
//   fx,fy,cx,cy  the still's intrinsics [px] (cx, cy move with the crop's margin)
//   mmPerUnit    depth unit in mm (1: mm; 0.2: TUM's value / 5000 m), default 1
//   frames       default 150, at 30 fps
// The crop is the still less 1/16 of its size on each side; the offset sweeps that
// margin horizontally with a 60-frame period and 5/6 of it vertically with a 90-frame one.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

struct CvImages;  // cv::Mat buffers (CvImages.hpp)

class StillPanReader final : public FrameSource {
 public:
  StillPanReader();
  ~StillPanReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override { return _frames; }
  double nominalFps() const override { return 30.0; }

 private:
  std::unique_ptr<CvImages> _img;
  std::string _name;
  Box _box{};
  CameraIntrinsics _k{};
  int _frames = 150, _next = 0;
  int _marginX = 0, _marginY = 0, _cropW = 0, _cropH = 0;  // [px]
  uint64_t _seed = 1;
  char _error[768] = "";
};

}  // namespace cuetrack
