// The listener's bookkeeping of the device's message numbers (seq, one counter per link,
// every message takes the next whether or not it reached the line). A jump forward is
// messages lost on the way; a jump back is the device restarting (it counts from 0
// again). Pure and small: fuzzed (tests/fuzz/listen) and unit-tested.
#pragma once

#include <cstdint>

namespace cuetrack::listen {

class SeqCounter {
 public:
  // An earlier run (or the time before a reconnect) ended after `lastSeq`: the next seq
  // seen is checked against it, so the messages in between are counted, not forgotten.
  void resumeAfter(uint32_t lastSeq) {
    _resumed = true;
    _last = lastSeq;
  }

  // One message's seq. Returns how many messages are missing just before it.
  uint32_t see(uint32_t seq) {
    uint32_t missing = 0;
    if (_have || _resumed) {
      if (seq > _last) {
        missing = seq - _last - 1;
      } else {
        // Back (or the same again): the device restarted and numbers from 0; the
        // messages of its new run before this one never arrived.
        ++_restarts;
        missing = seq;
      }
    }
    if (!_have) _first = seq;
    _have = true;
    _last = seq;
    _lost += missing;
    return missing;
  }

  bool any() const { return _have; }
  uint32_t first() const { return _first; }  // of this run; valid when any()
  uint32_t last() const { return _last; }    // or the resumed one before any()
  bool hasLast() const { return _have || _resumed; }
  uint64_t lost() const { return _lost; }
  uint32_t restarts() const { return _restarts; }

 private:
  bool _have = false, _resumed = false;
  uint32_t _first = 0, _last = 0;
  uint64_t _lost = 0;
  uint32_t _restarts = 0;
};

}  // namespace cuetrack::listen
