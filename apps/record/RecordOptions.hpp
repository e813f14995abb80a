// Command line of cuetrack-record, parsed into plain values (testable), through the
// tools' one command-line layer (apps/common).
#pragma once

#include <string>

#include "cuetrack/drivers/KinectSource.hpp"

namespace cuetrack::record {

// Exit codes (also printed by --help).
inline constexpr int kExitOk = 0;      // limit reached, SIGINT/SIGTERM/SIGHUP, or replay ended
inline constexpr int kExitDevice = 1;  // no Kinect, cannot open it, or the stream failed mid-run
inline constexpr int kExitUsage = 2;   // bad command line (the convention of every tool)
inline constexpr int kExitOutput = 3;  // cannot write the recording

enum class Format { Fakenect, Rgbd };

struct Options {
  std::string outDir;
  Format format = Format::Fakenect;
  int maxFrames = 0;        // 0 = no limit
  double maxSeconds = 0.0;  // [s] of camera time; 0 = no limit
  bool list = false;
  bool quiet = false;
  std::string serial;  // --serial; kinect.serial points into it
  KinectOptions kinect{};
};

// Parses argv into *out. Returns -1 to record, else what main returns: kExitOk after
// --help (kExitOutput when stdout failed), kExitUsage after one line on stderr.
int parse(int argc, const char* const* argv, Options* out);

}  // namespace cuetrack::record
