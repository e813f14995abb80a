// A source whose first frame the app already read (to pick a target on it, or to snapshot
// it) into the slot the pipeline uses: the first next() hands that frame on as it is, the
// rest come from the inner source.
#pragma once

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::app {

class PrefetchedSource final : public FrameSource {
 public:
  // The caller read inner's first frame into the slot later passed to next().
  explicit PrefetchedSource(FrameSource& inner) : _inner(inner) {}

  ReadStatus next(FrameSlot& out) override {
    if (_pending) {
      _pending = false;
      return ReadStatus::Ok;  // out still holds it: nobody else writes the slot
    }
    passIdleHookTo(_inner);
    return _inner.next(out);
  }
  const char* error() const override { return _inner.error(); }
  const char* name() const override { return _inner.name(); }
  int frameCount() const override { return _inner.frameCount(); }
  double nominalFps() const override { return _inner.nominalFps(); }
  int skippedFrames() const override { return _inner.skippedFrames(); }
  bool awaitingDevice() const override { return _inner.awaitingDevice(); }

 private:
  FrameSource& _inner;
  bool _pending = true;
};

}  // namespace cuetrack::app
