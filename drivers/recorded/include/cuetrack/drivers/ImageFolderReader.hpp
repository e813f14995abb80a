// What the two image-folder readers share (host only, cuetrack_recorded_cv): colour
// images (and 16-bit depth PNGs in mm) of a folder, paired by sorted file name, decoded
// through OpenCV into reused buffers. RgbdFolder.hpp and OtbFolder.hpp say where the
// images and the ground truth are.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "cuetrack/drivers/RecordedReader.hpp"

namespace cuetrack {

struct CvImages;  // cv::Mat buffers (CvImages.hpp)

class ImageFolderReader : public RecordedReader {
 public:
  ImageFolderReader();
  ~ImageFolderReader() override;
  int frameCount() const override { return static_cast<int>(_rgbFiles.size()); }
  double nominalFps() const override { return _fps; }

 protected:
  // The start of open(): dir without trailing '/', its name, no files yet.
  void startOpen(const char* dir, const SourceOptions& opt);
  // The image files of folder, sorted by name (zero-padded numbers sort right).
  bool listImages(const std::string& folder, std::vector<std::string>* out);
  // The end of open(): at least one image, and the ground truth (gtPath unless
  // SourceOptions::gtPath) when there is one.
  bool finishOpen(const std::string& gtPath, GtFormat format);

  std::string _dir;
  std::vector<std::string> _rgbFiles, _depthFiles;  // full paths; depth empty: none
  CameraIntrinsics _intrinsics{};
  bool _haveIntrinsics = false;
  double _fps = 30.0;

 private:
  FrameRead readFrame(int i, FrameSlot& out) override;
  uint64_t frameTimeUs(int i) const override;
  CameraIntrinsics frameIntrinsics(int widthPx, int heightPx) const override;
  bool readColour(const std::string& path, FrameSlot& out);
  bool readDepth(const std::string& path, FrameSlot& out);

  std::unique_ptr<CvImages> _img;
};

}  // namespace cuetrack
