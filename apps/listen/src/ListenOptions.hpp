// cuetrack-listen's command line, parsed into a plain struct (tested, fuzzed).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "cuetrack_proto.h"

namespace cuetrack::listen {

struct ListenOptions {
  static constexpr int kMaxSends = 32;
  // The texts as read; the pointers below point into them (nullptr: not given).
  std::string port, csv, state;
  std::vector<std::string> sendTexts;
  const char* portPath = nullptr;
  const char* csvPath = nullptr;
  const char* statePath = nullptr;  // --state FILE: the last seq across runs
  bool reconnect = false;           // wait for a port that went away
  long baud = 115200;
  long maxTracks = -1;  // --tracks N (>= 1), -1: no limit
  long idleS = -1;      // --idle-timeout S, -1: none
  long waitPortS = 5;   // --wait-port S: a PORT not there yet is waited for this long
  const char* sends[kMaxSends] = {};
  ctp_command_t commands[kMaxSends] = {};  // the --send texts, parsed, ids 1..N
  int numSends = 0;
};

enum class ListenParse { Run, Help, Error };

// Through the tools' command-line layer (apps/common). Error: one line in err (an
// unknown or repeated option, a bad value, a bad command, no PORT). Every --send is
// parsed here, before anything touches the port.
ListenParse parseListenOptions(int argc, char** argv, ListenOptions* out, char* err, size_t errLen);
// --help, generated from the same declarations.
std::string listenHelp();

}  // namespace cuetrack::listen
