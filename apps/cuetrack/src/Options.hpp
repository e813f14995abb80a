// The command line of `cuetrack`, parsed into a plain struct, through the tools' one
// command-line layer (apps/common).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

// Exit codes, also listed by --help.
enum ExitCode : int {
  kExitOk = 0,           // source ended, --frames reached, SIGINT/SIGTERM/SIGHUP, or STOP
  kExitSource = 1,       // source could not be opened, failed while reading, or changed size
  kExitUsage = 2,        // bad command line (the convention of every tool, README)
  kExitOutput = 3,       // --serial/--out could not be opened, or a file/stdout write failed
  kExitBoxRejected = 4,  // --box or ground-truth box refused by the tracker (outside...)
};

enum class Protocol : uint8_t { Cuetrack, Mavlink };

struct AppOptions {
  const char* source = nullptr;  // nullptr: Kinect when present, else the synthetic default
  bool hasBox = false;
  Box box{};
  bool useGroundTruth = true;
  const char* gtPath = nullptr;  // --gt FILE: the source's ground truth under another name
  const char* serialPath = nullptr;
  int baud = 115200;
  const char* outPath = nullptr;
  bool forceStdout = false;
  int frames = -1;
  const char* preset = "best";
  uint64_t seed = 1;
  bool quiet = false;
  bool realtime = false;       // play recordings and scenes at their own frame rate
  bool waitCamera = false;     // --source kinect: wait for one to be plugged in (WaitingSource)
  bool skipBadFrames = false;  // a recording's damaged frames are skipped (counted), not fatal
  Protocol protocol = Protocol::Cuetrack;   // on --serial
  int mavSysId = 1;                         // MAVLink system id (the vehicle's)
  int mavCompId = 100;                      // MAVLink component id (MAV_COMP_ID_CAMERA)
  float mountDeg[3] = {0.f, 0.f, 0.f};      // camera roll, pitch, yaw on the body [deg]
  float mountOffsetM[3] = {0.f, 0.f, 0.f};  // camera position in the body frame FRD [m]
  const char* mavlinkUdp = nullptr;         // --mavlink-udp HOST:PORT instead of --serial
  static constexpr int kMaxAcceptSysIds = 8;
  int acceptSysIds[kMaxAcceptSysIds] = {};  // --mavlink-accept-sysid: commands only from these
  int acceptSysIdCount = 0;                 // 0: from any system
  const char* mavlinkKey = nullptr;         // --mavlink-key FILE: MAVLink 2 signing
  bool landingPosition = true;              // --mavlink-landing frd (else angles)
  long mavlinkRateBytesPerS = 0;            // --mavlink-rate: output [bytes/s]; 0: the default
  const char* mavlinkOnlyOption = nullptr;  // the first --mavlink-* option given
  bool show = false;                        // --show: live window (View.hpp, host only)
  bool select = false;                      // --select: drag the target box on frame 1
  const char* snapshotPath = nullptr;       // --snapshot FILE.png: frame 1 + grid, then exit
  const char* videoPath = nullptr;          // --video FILE.avi: every frame with its track
  // The texts as read: the pointers above point into them (nullptr: not given).
  struct Texts {
    std::string source, serial, out, preset, mavlinkUdp, mavlinkKey, snapshot, video, gt;
  } texts;
};

enum class ParseResult : uint8_t { Run, Help, Error };

ParseResult parseOptions(int argc, char** argv, AppOptions* out, char* err, size_t errLen);
std::string usageText();  // --help, generated from the same declarations
inline constexpr const char* kDefaultScene = "moving";

}  // namespace cuetrack::app
