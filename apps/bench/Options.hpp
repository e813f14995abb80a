// Command line of cuetrack-bench (see usage()), through the tools' one command-line layer.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "Report.hpp"
#include "Runner.hpp"

namespace cuetrack::bench {

struct SequenceArg {
  std::string spec;    // path or "synth:<scene>"
  std::string gtPath;  // --gt given before it; empty = the reader's default
  // --from / --to / --reverse given before it (sliceSequence)
  int fromIndex = -1;    // frames with a smaller index left out (-1: none)
  int toIndex = -1;      // frames with a larger index left out (-1: none)
  bool reverse = false;  // the kept frames played backwards
};

struct Options {
  std::vector<SequenceArg> sequences;
  std::vector<EntrySpec> entries;  // tracker x configuration, in table order
  int runs = 10;
  int peerRuns = -1;  // -1: same as runs
  uint64_t seed = 1;
  int maxFrames = 0;  // 0: whole sequences
  int stride = 1;     // --stride: every stride-th frame after the first box
  int dropPct = 0;    // --drop-frames: of those, this percent dropped at random
  size_t maxMemMiB = 4096;
  bool skipBadFrames = false;
  bool rgbOnly = false;  // drop the depth of every sequence (tests the trackers' RGB-only mode)
  bool quiet = false;
  std::string jsonPath, markdownPath, csvDir, plotDir, resultsDir, overlayDir, videoDir;
  std::string peerCacheDir;  // --peer-cache: the OpenCV peers' results, reused (PeerCache.hpp)
  PaperReference paper = PaperReference::None;
};

// --help, generated from the declarations (apps/common's command-line layer).
std::string usage();
// False with one line in *err for a bad command line; *help when -h/--help was given.
bool parseOptions(int argc, const char* const* argv, Options* out, bool* help, std::string* err);

}  // namespace cuetrack::bench
