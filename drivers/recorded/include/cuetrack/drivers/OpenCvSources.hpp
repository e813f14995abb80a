// OpenCV-backed readers and writers (host only; library cuetrack_recorded_cv, built
// when CUETRACK_WITH_OPENCV). No OpenCV type appears here: decoders live in the .cpp.
//
//   BobotVideoReader  NAME.avi + NAME.gt.txt (or SourceOptions::gtPath); frame N <-> GT N;
//                     a frame FFmpeg reports errors for while decoding is damaged
//   RgbdFolderReader  rgb/*.png, depth/*.png (16-bit mm), groundtruth.txt (BoBoT),
//                     intrinsics.txt ("fx fy cx cy"); images paired by sorted file name
//   OtbFolderReader   img/0001.jpg ..., groundtruth_rect.txt (x,y,w,h 1-based px)
//   RgbdFolderWriter  writes the RGB-D folder layout (rgb/000000.png ...)
// OpenCV's decoders allocate inside OpenCV; the readers reuse their cv::Mat buffers.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/GroundTruth.hpp"
#include "cuetrack/drivers/SourceOptions.hpp"

namespace cuetrack {

struct CvImages;  // cv::Mat buffers, defined in the .cpp

class BobotVideoReader final : public FrameSource {
 public:
  BobotVideoReader();
  ~BobotVideoReader() override;
  bool open(const char* aviPath, const SourceOptions& opt = {});
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override { return _frameCount; }
  double nominalFps() const override { return _fps; }
  int skippedFrames() const override { return _skipped; }
  const GroundTruth& groundTruth() const { return _gt; }

 private:
  struct Video;
  std::unique_ptr<Video> _video;
  std::unique_ptr<CvImages> _img;
  std::string _path, _name;
  GroundTruth _gt;
  SourceOptions _opt{};
  int _frameCount = -1;
  int _next = 0;
  int _skipped = 0;
  int _width = 0, _height = 0;  // of the first frame read: every frame must match
  double _fps = 25.0;
  char _error[512] = "";
};

// Common base of the two image-folder readers.
class ImageFolderReader : public FrameSource {
 public:
  ImageFolderReader();
  ~ImageFolderReader() override;
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override { return static_cast<int>(_rgbFiles.size()); }
  double nominalFps() const override { return _fps; }
  int skippedFrames() const override { return _skipped; }

 protected:
  bool finishOpen(const char* gtPath, GtFormat format, bool gtRequired);
  std::string _dir, _name;
  std::vector<std::string> _rgbFiles, _depthFiles;  // full paths; depth empty: none
  CameraIntrinsics _intrinsics{};
  bool _haveIntrinsics = false;
  GroundTruth _gt;
  SourceOptions _opt{};
  double _fps = 30.0;
  int _next = 0;
  int _emitted = 0;
  int _skipped = 0;
  int _width = 0, _height = 0;  // of the first frame read: every frame must match
  std::unique_ptr<CvImages> _img;
  char _error[768] = "";
};

class RgbdFolderReader final : public ImageFolderReader {
 public:
  bool open(const char* dir, const SourceOptions& opt = {});
};

class OtbFolderReader final : public ImageFolderReader {
 public:
  bool open(const char* dir, const SourceOptions& opt = {});
};

// A real RGB-D still panned: each frame is a crop of the still whose offset sweeps
// sinusoidally (a camera panning and tilting by a few degrees: at these angles the image
// shifts, the depth of every point stays), with fresh colour noise (sigma 2 levels) per
// frame and the still's own depth. The ground truth is the given box, shifted with the
// crop. Spec (openFrameSource): pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames]
//   RGB, DEPTH   colour image and 16-bit depth image (PNG or PGM), registered
//   x,y,w,h      the target's box in the still [px]
//   fx,fy,cx,cy  the still's intrinsics [px] (cx, cy move with the crop's margin)
//   mmPerUnit    depth unit in mm (1: mm; 0.2: TUM's value / 5000 m), default 1
//   frames       default 150, at 30 fps
// The crop is the still less 1/16 of its size on each side; the offset sweeps that
// margin horizontally with a 60-frame period and 5/6 of it vertically with a 90-frame one.
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
  int _marginX = 0, _marginY = 0, _cropW = 0, _cropH = 0;
  uint64_t _seed = 1;
  char _error[768] = "";
};

class SyntheticSource;

// A synthetic scene's objects in a real RGB-D still: each frame is the still (colour and
// depth) with the scene's objects (not its procedural wall and floor) drawn over it by
// SyntheticSource::setBackdrop, a z-test against the still's depth (a real surface in
// front hides them, a hole does not), their depth through the synthetic Kinect model
// (disparity noise, quantisation, the projector's shadow, also cast on the still), fresh
// colour noise per frame, and the scene's exact ground truth (the visible target's box).
// The scene is moved as a whole (placeInStill) so that the target's motion start stands
// on pixel u,v, its back gapMm in front of the still's depth there. Spec (openFrameSource):
//   still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames]
//   RGB, DEPTH   colour image and 16-bit depth image (PNG or PGM), registered
//   fx,fy,cx,cy  the still's intrinsics [px]
//   mmPerUnit    depth unit in mm (1: mm; 0.2: TUM's value / 5000 m), default 1
//   SCENE        a synth: scene name (makeScene)
//   frames       default the scene's (150), at its 30 fps
// Deterministic by SourceOptions::seed, like the synth: scenes.
class StillSceneReader final : public FrameSource {
 public:
  StillSceneReader();
  ~StillSceneReader() override;
  bool open(const char* spec, const SourceOptions& opt = {});
  ReadStatus next(FrameSlot& out) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name.c_str(); }
  int frameCount() const override;
  double nominalFps() const override;
  // The scene rendered (truth() for the last frame); nullptr before a successful open().
  const SyntheticSource* scene() const { return _scene.get(); }

 private:
  struct Still;
  std::unique_ptr<Still> _still;  // colour and depth, ~1.5 MiB, read once
  std::unique_ptr<SyntheticSource> _scene;
  std::string _name;
  char _error[768] = "";
};

class RgbdFolderWriter {
 public:
  RgbdFolderWriter() = default;
  // Creates dir/rgb and dir/depth; sequenceName heads groundtruth.txt (default: dir's name).
  // Refuses a dir that already holds a recording (rec::holdsRecording).
  bool open(const char* dir, const char* sequenceName = nullptr);
  bool write(const FrameSlot& frame);
  bool close();
  const char* error() const { return _error; }  // one line naming the file at fault
  int framesWritten() const { return _count; }

 private:
  std::string _dir, _name;
  GtWriter _gt;
  bool _gtOpen = false;
  bool _wroteIntrinsics = false;
  int _count = 0;
  char _error[512] = "";
};

// OTB folder: img/0001.jpg ... (JPEG quality 95, colour only) + groundtruth_rect.txt.
class OtbFolderWriter {
 public:
  bool open(const char* dir);
  bool write(const FrameSlot& frame);
  bool close();
  const char* error() const { return _error; }

 private:
  std::string _dir;
  GtWriter _gt;
  int _count = 0;
  char _error[512] = "";
};

// BoBoT-style video: PATH.avi (Motion-JPEG, colour only) + PATH.gt.txt (BoBoT format,
// header "./NAME.avi"). fps is the container's rate (1..1000). Every frame must have the
// first one's size; close() reads the video back and fails unless every frame written
// decodes (OpenCV's writer reports no write error, e.g. on a full disk).
class BobotVideoWriter {
 public:
  BobotVideoWriter();
  ~BobotVideoWriter();
  bool open(const char* aviPath, double fps = 30.0);
  bool write(const FrameSlot& frame);
  bool close();
  const char* error() const { return _error; }

 private:
  struct Video;
  std::unique_ptr<Video> _video;
  std::string _path;
  GtWriter _gt;
  double _fps = 30.0;
  int _count = 0;
  int _width = 0, _height = 0;
  char _error[512] = "";
};

// Stills: 16-bit PNG depth (as stored; the caller scales, e.g. TUM's value / 5 = mm)
// and any colour image OpenCV reads. Sizes up to kMaxImageWidth x kMaxImageHeight.
bool loadDepthPng16(const char* path, FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight>& out,
                    char* err, size_t errLen);
bool loadColourImage(const char* path, FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight>& out,
                     char* err, size_t errLen);

}  // namespace cuetrack
