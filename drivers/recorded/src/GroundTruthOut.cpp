#include "cuetrack/drivers/GroundTruthOut.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cuetrack {

void GroundTruthOut::start(const std::string& dir, const std::string& sequenceName) {
  _dir = dir;
  _name = sequenceName;
  _open = false;
}

bool GroundTruthOut::write(const FrameSlot& frame, int index, char* err, size_t errLen) {
  if (!frame.hasGroundTruth) return true;
  if (!_open) {
    if (index > 0) {
      std::snprintf(err, errLen, "%s: ground truth starts at frame %d, not 0", _dir.c_str(), index);
      return false;
    }
    if (!_gt.open((_dir + "/groundtruth.txt").c_str(), GtFormat::Bobot, _name.c_str(), err, errLen))
      return false;
    _open = true;
  }
  _gt.write(frame.groundTruth, frame.rgb.width(), frame.rgb.height());
  return true;
}

bool GroundTruthOut::close(char* err, size_t errLen) {
  if (!_open) return true;
  _open = false;
  if (_gt.close()) return true;
  std::snprintf(err, errLen, "%s/groundtruth.txt: write failed (%s)", _dir.c_str(),
                std::strerror(errno));
  return false;
}

}  // namespace cuetrack
