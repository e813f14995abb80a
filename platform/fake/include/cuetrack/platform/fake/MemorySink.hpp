// Keeps track messages in a fixed array; can be told to fail, like a full disk.
#pragma once

#include <cstddef>

#include "cuetrack/platform/TrackSink.hpp"

namespace cuetrack::platform {

class MemorySink final : public TrackSink {
 public:
  static constexpr size_t kCapacity = 4096;

  bool write(const ctp_track_t& track) override;
  const char* error() const override { return _error; }
  const char* name() const override { return "memory"; }

  size_t size() const { return _count; }
  const ctp_track_t& at(size_t i) const { return _tracks[i]; }
  size_t overflowed() const { return _overflowed; }
  void setFailing(bool failing) { _failing = failing; }
  void clear() { _count = 0; }

 private:
  ctp_track_t _tracks[kCapacity]{};
  size_t _count{0};
  size_t _overflowed{0};
  bool _failing{false};
  char _error[64]{};
};

}  // namespace cuetrack::platform
