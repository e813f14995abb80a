// Options every recorded-sequence reader (and the openFrameSource factory) takes.
#pragma once

#include <cstdint>

namespace cuetrack {

struct SourceOptions {
  bool skipBadFrames = false;    // skip unreadable frames (counted) instead of stopping
  const char* gtPath = nullptr;  // ground-truth file overriding the one beside the sequence
  // The target comes from elsewhere (a --box): ground truth beside the sequence that does
  // not parse or does not fit (a stray NAME.txt of notes) is left out with a warning()
  // instead of failing the source.
  bool groundTruthOptional = false;
  int maxFrames = -1;  // stop after this many frames (-1: all)
  uint64_t seed = 1;   // synthetic scenes only
};

}  // namespace cuetrack
