// Options every recorded-sequence reader (and the openFrameSource factory) takes.
#pragma once

#include <cstdint>

namespace cuetrack {

struct SourceOptions {
  bool skipBadFrames = false;    // skip unreadable frames (counted) instead of stopping
  const char* gtPath = nullptr;  // ground-truth file overriding the one beside the sequence
  int maxFrames = -1;            // stop after this many frames (-1: all)
  uint64_t seed = 1;             // synthetic scenes only
};

}  // namespace cuetrack
