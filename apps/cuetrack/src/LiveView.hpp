// --show: the live window. Its own thread renders the latest pushed frame; push() only
// copies the pixels into a mailbox (LatestMailbox) and never waits for the window.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "Picker.hpp"
#include "ViewTrack.hpp"
#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

class LiveView {
 public:
  LiveView();
  ~LiveView();
  LiveView(const LiveView&) = delete;
  LiveView& operator=(const LiveView&) = delete;

  // Opens the window thread; stop() (the signal flag) also ends a re-select (r) open in it.
  bool start(bool (*stop)(), char* err, size_t errLen);
  // pickBox() on the window's thread: with --show, every highgui call must come from the
  // one thread (Qt's GUI thread is the first that used it). stop() ends it (Interrupted).
  PickResult pick(const Frame& frame, bool (*stop)(), Box* out, char* err, size_t errLen);
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
