#include "OutputCheck.hpp"

#include <cstdio>
#include <string>

#include "cuetrack/cli/OutputGuard.hpp"

namespace cuetrack::app {

bool checkOutputs(const AppOptions& opt, char* err, size_t errLen) {
  cli::OutputGuard guard;
  if (opt.source) guard.source("--source", opt.source);
  if (opt.gtPath) guard.input("--gt", opt.gtPath);
  if (opt.mavlinkKey) guard.input("--mavlink-key", opt.mavlinkKey);
  if (opt.outPath) guard.output("--out", opt.outPath);
  if (opt.videoPath) guard.output("--video", opt.videoPath);
  if (opt.snapshotPath) guard.output("--snapshot", opt.snapshotPath);
  std::string why;
  if (guard.check(&why)) return true;
  std::snprintf(err, errLen, "%s", why.c_str());
  return false;
}

}  // namespace cuetrack::app
