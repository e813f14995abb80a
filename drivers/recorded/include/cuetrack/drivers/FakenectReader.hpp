// fakenect recordings (libfreenect's fakenect-record): INDEX.txt naming
// r-<s>-<ts>.ppm colour, d-<s>-<ts>.pgm raw 11-bit depth ("P5 640 480 65535\n" +
// little-endian uint16) and a-<s>-<ts>.dump accelerometer files, plus an optional
// groundtruth.txt (BoBoT format) beside INDEX.txt.
//
// One frame per colour entry; its depth is the last depth entry before it in INDEX
// (the one fakenect would have delivered last), or the first one after it when none
// came before. Time is the seconds field relative to the first INDEX entry. Raw
// disparity becomes mm with kinect::rawToMm. No decoding library: runs on the board.
// After the first frame, reading allocates nothing (buffers are reused).
#pragma once

#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "cuetrack/drivers/KinectDepth.hpp"
#include "cuetrack/drivers/RecordedReader.hpp"

namespace cuetrack {

class FakenectReader final : public RecordedReader {
 public:
  FakenectReader() = default;
  // Reads INDEX.txt (and groundtruth.txt); false with error() on failure.
  bool open(const char* dir, const SourceOptions& opt = {});

  int frameCount() const override { return static_cast<int>(_frames.size()); }
  // Colour frames per second over the recording (first to last colour entry), 0 for one frame.
  double nominalFps() const override { return _fps; }

 private:
  struct Frame {
    int rgbEntry;
    int depthEntry;  // -1: none
  };
  FrameRead readFrame(int i, FrameSlot& out) override;
  uint64_t frameTimeUs(int i) const override;
  bool readPair(const Frame& f, FrameSlot& out);
  void entryPath(int entry, char* path, size_t len) const;

  std::string _dir;
  std::vector<std::string> _files;  // INDEX entries, in order
  std::vector<double> _seconds;
  std::vector<Frame> _frames;
  double _t0 = 0.0;
  double _fps = 0.0;
  std::vector<uint8_t> _buf;
  kinect::RawToMmTable _rawToMm;
};

// Whether libfreenect's fakenect can replay the recording in `dir`: it exit()s on an INDEX
// line it cannot parse or a file it cannot open, and overruns its fixed 640x480 buffers on
// other sizes. Checks every INDEX entry (name, a regular file, and for r-*.ppm / d-*.pgm a
// 640x480 header of the right kind); false with "file: reason" (one line) in err.
bool checkFakenectReplayable(const char* dir, char* err, size_t errLen);

}  // namespace cuetrack
