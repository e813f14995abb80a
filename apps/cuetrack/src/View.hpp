// What cuetrack shows on a screen (host builds with OpenCV's highgui): the live window
// (--show), the target picker (--select) and the grid snapshot (--snapshot). Board builds
// link ViewStub.cpp instead, whose every call fails with "not built with OpenCV".
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "cuetrack/core/Frame.hpp"
#include "cuetrack/core/Geometry.hpp"

namespace cuetrack::app {

// This build has OpenCV's highgui/videoio (--snapshot, --video, --show, --select).
bool viewBuilt();

// This build can open windows (OpenCV highgui) and $DISPLAY names a display; else false
// and one line in err naming what is missing.
bool displayAvailable(char* err, size_t errLen);

// Shows frame and lets the user drag a box (cv::selectROI; Enter/space accepts, c or Esc
// cancels). False + one line in err on cancel or an empty box.
bool pickBox(const Frame& frame, Box* out, char* err, size_t errLen);

// Writes frame as a PNG with a labelled pixel grid every kSnapshotGridPx, so a box can be
// read off it on a machine without a display. False + one line in err.
inline constexpr int kSnapshotGridPx = 40;
bool writeSnapshot(const Frame& frame, const char* path, char* err, size_t errLen);

// The frame as the tracker left it, for the window.
struct ViewTrack {
  uint32_t frameIndex = 0;
  uint8_t state = 0;  // CTP_STATE_*
  Box box{};          // [px]
  float confidence = 0.f;
};

// --video FILE.avi: every frame with its track drawn (Motion JPEG), written on the caller's
// thread, so it costs the tracker's loop an encode per frame (a few ms).
class VideoOut {
 public:
  VideoOut();
  ~VideoOut();
  VideoOut(const VideoOut&) = delete;
  VideoOut& operator=(const VideoOut&) = delete;

  bool open(const char* path, double fps, char* err, size_t errLen);  // fps 0: 30
  bool write(const Frame& frame, const ViewTrack& track, char* err, size_t errLen);
  bool close(char* err, size_t errLen);  // false: the file is missing or empty
  uint32_t frames() const { return _frames; }

 private:
  struct Impl;
  std::unique_ptr<Impl> _impl;
  uint32_t _frames = 0;
};

// The live window: its own thread renders the latest pushed frame; push() only copies the
// pixels into a mailbox (LatestMailbox) and never waits for the window.
class LiveView {
 public:
  LiveView();
  ~LiveView();
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  bool start(char* err, size_t errLen);  // opens the window thread
  // pickBox() on the window's thread: with --show, every highgui call must come from the
  // one thread (Qt's GUI thread is the first that used it).
  bool pick(const Frame& frame, Box* out, char* err, size_t errLen);
  void push(const Frame& frame, const ViewTrack& track);
  // Space paused the run: blocks until resumed, quit, or stop() returns true.
  void waitWhilePaused(bool (*stop)());
  // A box the user dragged after pressing r, for a restart on the next frame.
  bool takeReselect(Box* box);
  bool quitRequested() const;  // q, Esc, or the window closed
  uint64_t droppedFrames() const;
  void close();  // ends the window thread

 private:
  struct Impl;
  std::unique_ptr<Impl> _impl;
};

}  // namespace cuetrack::app
