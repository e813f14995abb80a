// Writes frames as a fakenect recording that libfreenect's fakenect replays and
// FakenectReader reads (see FakenectReader.hpp for the layout).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cuetrack/drivers/FrameSource.hpp"
#include "cuetrack/drivers/GroundTruthOut.hpp"
#include "cuetrack/drivers/KinectDepth.hpp"

namespace cuetrack {

// Writes frames as a fakenect recording (INDEX.txt, d-/r-/a- files, groundtruth.txt
// in BoBoT format when frames carry ground truth). Depth [mm] -> raw with
// kinect::mmToRaw. Only 640x480 is valid for fakenect replay; other sizes are written
// as they are (our reader takes them; libfreenect's fakenect cannot replay them).
class FakenectWriter {
 public:
  FakenectWriter() = default;
  FakenectWriter(const FakenectWriter&) = delete;
  FakenectWriter& operator=(const FakenectWriter&) = delete;
  ~FakenectWriter();
  // Creates dir (and parents); sequenceName heads groundtruth.txt (default: dir's name).
  // Refuses a dir that already holds a recording (rec::holdsRecording).
  bool open(const char* dir, const char* sequenceName = nullptr);
  bool write(const FrameSlot& frame);
  bool close();
  // Last error as one line naming the file at fault.
  const char* error() const { return _error; }
  int framesWritten() const { return _count; }

 private:
  std::string _dir;
  std::string _name;
  std::FILE* _index = nullptr;
  GroundTruthOut _gt;
  int _count = 0;
  std::vector<uint8_t> _buf;
  uint16_t _mmToRaw[kMaxDepthMm + 1];  // depth [mm] -> raw disparity, built at open (20 KiB)
  bool _tableReady = false;
  char _error[512] = "";
};

}  // namespace cuetrack
