// A source whose first frame the app already read (to pick a target on it, or to snapshot
// it) into the slot the pipeline uses: the first next() hands that frame on as it is, the
// rest come from the inner source.
#pragma once

#include "ForwardingSource.hpp"

namespace cuetrack::app {

class PrefetchedSource final : public ForwardingSource {
 public:
  // The caller read inner's first frame into the slot later passed to next().
  explicit PrefetchedSource(FrameSource& inner) : ForwardingSource(&inner) {}

  ReadStatus next(FrameSlot& out) override {
    if (_pending) {
      _pending = false;
      return ReadStatus::Ok;  // out still holds it: nobody else writes the slot
    }
    return forwardNext(out);
  }

 private:
  bool _pending = true;
};

}  // namespace cuetrack::app
