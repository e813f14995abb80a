// The base of the sources that wrap another (PacedSource, PrefetchedSource, WaitingSource):
// every call of the FrameSource interface goes on to the wrapped source, so a wrapper
// overrides only what it changes. next() hands the caller's idle hook on first, so a
// wait inside the wrapped source still serves the link.
#pragma once

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::app {

class ForwardingSource : public FrameSource {
 public:
  ReadStatus next(FrameSlot& out) override { return forwardNext(out); }
  // No wrapped source yet (WaitingSource before its camera): FrameSource's defaults.
  const char* error() const override { return _inner ? _inner->error() : ""; }
  const char* name() const override { return _inner ? _inner->name() : ""; }
  int frameCount() const override { return _inner ? _inner->frameCount() : -1; }
  double nominalFps() const override { return _inner ? _inner->nominalFps() : 0.0; }
  int skippedFrames() const override { return _inner ? _inner->skippedFrames() : 0; }
  bool awaitingDevice() const override { return _inner ? _inner->awaitingDevice() : false; }

 protected:
  explicit ForwardingSource(FrameSource* inner) : _inner(inner) {}

  FrameSource* inner() const { return _inner; }
  void setInner(FrameSource* inner) { _inner = inner; }
  // The wrapped source's next frame, with the caller's idle hook passed on; needs inner().
  ReadStatus forwardNext(FrameSlot& out) {
    passIdleHookTo(*_inner);
    return _inner->next(out);
  }

 private:
  FrameSource* _inner;
};

}  // namespace cuetrack::app
