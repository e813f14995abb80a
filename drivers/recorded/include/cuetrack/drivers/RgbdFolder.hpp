// RGB-D sequence folders (host only, cuetrack_recorded_cv): rgb/*.png, depth/*.png
// (16-bit, mm), groundtruth.txt (BoBoT format), intrinsics.txt ("fx fy cx cy" [px]);
// colour and depth paired by sorted file name.
#pragma once

#include <string>

#include "cuetrack/drivers/GroundTruthOut.hpp"
#include "cuetrack/drivers/ImageFolderReader.hpp"

namespace cuetrack {

class RgbdFolderReader final : public ImageFolderReader {
 public:
  bool open(const char* dir, const SourceOptions& opt = {});
};

// Writes the layout (rgb/000000.png ...), intrinsics.txt from the first frame and
// groundtruth.txt when the frames carry truth.
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
  GroundTruthOut _gt;
  bool _wroteIntrinsics = false;
  int _count = 0;
  char _error[512] = "";
};

}  // namespace cuetrack
