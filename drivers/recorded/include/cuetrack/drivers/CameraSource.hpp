// Any V4L2/UVC camera (a laptop's webcam, a USB camera) through OpenCV's V4L2 backend
// (host only, cuetrack_recorded_cv): colour only, at the camera's own rate and size; a
// frame larger than the tracker's working size is scaled down (FrameScale.hpp). No OpenCV
// type appears here.
//
//   camera             /dev/video0
//   camera:N           /dev/videoN
//   camera:/dev/PATH   that device (e.g. /dev/v4l/by-id/...)
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack {

struct CvImages;  // cv::Mat buffers (CvImages.hpp)

class CameraSource final : public FrameSource {
 public:
  CameraSource();
  ~CameraSource() override;
  // spec as above. False with one line naming the device: no such device, or one that
  // is not a capture device (busy, or not a camera).
  bool open(const char* spec);
  // The same reader on a video file (FFmpeg instead of V4L2), frames timed by the file's
  // rate: how it is tested on a machine without a camera.
  bool openVideoFile(const char* path);

  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  double nominalFps() const override { return _fps; }
  const char* device() const { return _device.c_str(); }

 private:
  struct Capture;
  std::unique_ptr<Capture> _cap;
  std::unique_ptr<CvImages> _img;
  std::string _device, _name;
  bool _live = true;            // a camera: frames timed by the clock, a failed read an error
  double _fps = 0.0;            // as the device or file reports it; 0: unknown
  int _index = 0;               // next frame's index
  int _width = 0, _height = 0;  // [px] of the first frame, the source's own
  char _error[512] = "";
};

// The device a spec names ("camera" -> /dev/video0, "camera:2" -> /dev/video2); false
// with one line in err for a malformed spec.
bool cameraDevice(const char* spec, std::string* device, char* err, size_t errLen);
// The first /dev/video0../dev/video9 that opens as a V4L2 capture device, for the default
// source; false when there is none.
bool findCamera(std::string* device);

}  // namespace cuetrack
