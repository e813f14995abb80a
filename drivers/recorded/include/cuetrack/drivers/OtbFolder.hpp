// OTB sequence folders (host only, cuetrack_recorded_cv): img/0001.jpg ..., colour only,
// and groundtruth_rect.txt (x,y,w,h in 1-based pixels, one line per frame). A plain image
// folder (images directly inside, no img/) reads the same way, its groundtruth_rect.txt
// inside it too. Images larger than the tracker's working size are scaled down
// (FrameScale.hpp); the ground truth stays in the images' own pixels.
#pragma once

#include <string>

#include "cuetrack/drivers/GroundTruth.hpp"
#include "cuetrack/drivers/ImageFolderReader.hpp"

namespace cuetrack {

class OtbFolderReader final : public ImageFolderReader {
 public:
  bool open(const char* dir, const SourceOptions& opt = {});
};

// Writes img/0001.jpg ... (JPEG quality 95) and groundtruth_rect.txt.
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

}  // namespace cuetrack
