// Command line of cuetrack-record, parsed into plain values (no allocation, testable).
#pragma once

#include <cstddef>
#include <cstdio>

#include "cuetrack/drivers/KinectSource.hpp"

namespace cuetrack::record {

// Exit codes (also printed by --help).
inline constexpr int kExitOk = 0;      // limit reached, SIGINT/SIGTERM/SIGHUP, or replay ended
inline constexpr int kExitDevice = 1;  // no Kinect, cannot open it, or the stream failed mid-run
inline constexpr int kExitUsage = 2;   // bad command line (the convention of every tool)
inline constexpr int kExitOutput = 3;  // cannot write the recording

enum class Format { Fakenect, Rgbd };

struct Options {
  const char* outDir = nullptr;
  Format format = Format::Fakenect;
  int maxFrames = 0;        // 0 = no limit
  double maxSeconds = 0.0;  // [s] of camera time; 0 = no limit
  bool list = false;
  bool quiet = false;
  KinectOptions kinect{};
};

enum class ParseResult { Ok, Help, Error };

ParseResult parse(int argc, char** argv, Options* out, char* err, std::size_t errLen);
void usage(std::FILE* to);

}  // namespace cuetrack::record
