// The ground truth a recording writer puts beside its frames (FakenectWriter,
// RgbdFolderWriter): DIR/groundtruth.txt in BoBoT form, headed by the sequence name,
// created at the first frame that carries ground truth (which must be frame 0), one line
// per frame from then on. No decoding library: the board builds it.
#pragma once

#include <cstddef>
#include <string>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/GroundTruth.hpp"

namespace cuetrack {

class GroundTruthOut {
 public:
  // A new recording in dir; nothing is created until a frame carries ground truth.
  void start(const std::string& dir, const std::string& sequenceName);
  // Frame `index` (0-based) of the recording: its box, when it has ground truth. False
  // with one line in err when ground truth starts after frame 0 or the file cannot be made.
  bool write(const FrameSlot& frame, int index, char* err, size_t errLen);
  // Closes the file, if one was made. False with "DIR/groundtruth.txt: write failed
  // (REASON)" in err when what was written did not reach the disk.
  bool close(char* err, size_t errLen);

 private:
  std::string _dir, _name;
  GtWriter _gt;
  bool _open = false;
};

}  // namespace cuetrack
