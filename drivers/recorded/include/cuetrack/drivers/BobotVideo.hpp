// Videos (host only, cuetrack_recorded_cv): BoBoT's NAME.avi + NAME.gt.txt (ground truth in
// the BoBoT format, frame N <-> box N), and any other video FFmpeg decodes (.mp4, .mkv,
// .mov, ...; ground truth beside it as MediaFiles.hpp says). Colour only; a frame larger
// than the tracker's working size is scaled down (FrameScale.hpp), the ground truth read in
// the video's own pixels. No OpenCV type appears here.
#pragma once

#include <memory>
#include <string>

#include "cuetrack/drivers/GroundTruth.hpp"
#include "cuetrack/drivers/RecordedReader.hpp"

namespace cuetrack {

struct CvImages;  // cv::Mat buffers (CvImages.hpp)

// NAME.gt.txt or NAME.txt (or SourceOptions::gtPath) beside NAME.EXT; a frame FFmpeg reports errors
// for while decoding is damaged (Bad: skipped with skipBadFrames), and a video that ends
// before its container's frame count or its ground truth's boxes is truncated.
class BobotVideoReader final : public RecordedReader {
 public:
  BobotVideoReader();
  ~BobotVideoReader() override;
  bool open(const char* videoPath, const SourceOptions& opt = {});
  int frameCount() const override { return _frameCount; }
  double nominalFps() const override { return _fps; }
  const GroundTruth& groundTruth() const { return _gt; }

 private:
  FrameRead readFrame(int i, FrameSlot& out) override;
  uint64_t frameTimeUs(int i) const override;

  struct Video;
  std::unique_ptr<Video> _video;
  std::unique_ptr<CvImages> _img;
  std::string _path;
  int _frameCount = -1;  // as the container announces it; -1: unknown
  double _fps = 25.0;
};

// PATH.avi (Motion-JPEG, colour only) + PATH.gt.txt (BoBoT format, header "./NAME.avi").
// fps is the container's rate (1..1000). Every frame must have the first one's size;
// close() reads the video back and fails unless every frame written decodes (OpenCV's
// writer reports no write error, e.g. on a full disk).
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
  int _width = 0, _height = 0;  // [px] of the first frame written
  char _error[512] = "";
};

}  // namespace cuetrack
