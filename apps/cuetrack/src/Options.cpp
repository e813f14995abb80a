#include "Options.hpp"

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cuetrack/platform/DecimalText.hpp"
#include "cuetrack/platform/HostPort.hpp"
#include "cuetrack/platform/OptionOnce.hpp"

namespace cuetrack::app {
namespace {

constexpr float kMaxBoxPx = 100000.f;  // far beyond any sensor; catches 1e30 and typos

bool parseLong(const char* s, long lo, long hi, long* out) {
  if (!platform::plainDecimal(s, false)) return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || errno != 0 || v < lo || v > hi) return false;
  *out = v;
  return true;
}

// n finite numbers "A,B,...", each within +-limit.
bool parseFloats(const char* s, int n, float limit, float* out) {
  for (int i = 0; i < n; ++i) {
    if (!platform::plainDecimal(s, true, ',')) return false;
    char* end = nullptr;
    out[i] = std::strtof(s, &end);
    // inf, nan and absurd values would reach the tracker as something it "tracks".
    if (end == s || !std::isfinite(out[i]) || std::fabs(out[i]) > limit) return false;
    s = end;
    if (i < n - 1) {
      if (*s != ',') return false;
      ++s;
    }
  }
  return *s == '\0';
}

// "N[,N...]": MAVLink system ids, 1..255 each (0 is "every system", never a sender).
bool parseSysIds(const char* s, int* ids, int cap, int* count) {
  *count = 0;
  for (;;) {
    char token[8];
    size_t n = 0;
    while (s[n] != '\0' && s[n] != ',' && n < sizeof token - 1) {
      token[n] = s[n];
      ++n;
    }
    token[n] = '\0';
    long id = 0;
    if (*count >= cap || (s[n] != '\0' && s[n] != ',') || !parseLong(token, 1, 255, &id))
      return false;
    ids[(*count)++] = static_cast<int>(id);
    if (s[n] == '\0') return true;
    s += n + 1;
  }
}

bool parseBox(const char* s, Box* out) {
  float v[4];
  if (!parseFloats(s, 4, kMaxBoxPx, v) || !(v[2] > 0.f) || !(v[3] > 0.f)) return false;
  *out = Box{v[0], v[1], v[2], v[3]};
  return true;
}

}  // namespace

const char* usageText() {
  return "usage: cuetrack [options]\n"
         "Tracks an object in RGB-D frames and streams the track (docs/serial-protocol.md,\n"
         "docs/mavlink.md).\n"
         "\n"
         "source (default: the Kinect when one is plugged in, else the synthetic scene 'moving'):\n"
         "  --source kinect[:colour]|synth[:SCENE]|PATH\n"
         "                                       kinect:colour streams colour only: 2D\n"
         "                                       tracking, 9.2 instead of 21.9 MB/s of USB\n"
         "                                       (docs/kinect.md)\n"
         "                                       SCENE: one of cuetrack-synth --list (15 scenes,\n"
         "                                       docs/recordings.md); PATH: a fakenect\n"
         "                                       recording folder (host builds with OpenCV\n"
         "                                       also read RGB-D folders, OTB folders, .avi,\n"
         "                                       and pan:/still: stills; docs/recordings.md)\n"
         "target (default: the ground truth where the target first shows, else wait for START):\n"
         "  --box X,Y,W,H      target box in the first frame [px]\n"
         "  --no-gt            ignore ground truth: wait for --box or a serial START command\n"
         "  --select           show the first frame and drag a box around the target; prints\n"
         "                     it as --box X,Y,W,H for later runs (needs a display)\n"
         "  --snapshot FILE.png\n"
         "                     save the first frame with a pixel grid (every 40 px) and exit,\n"
         "                     to read a --box off it on a board without a display\n"
         "see it (host builds with OpenCV, needs a display):\n"
         "  --show             live window: box, state, confidence, fps, depth beside it;\n"
         "                     space pauses, r re-selects the target, q or Esc quits\n"
         "  --video FILE.avi   write every frame with its box, state, confidence and frame\n"
         "                     number drawn (Motion JPEG; no display needed)\n"
         "outputs (stdout gets one line per frame when neither --serial nor --out is given,\n"
         "and stdout is not a terminal: there, only with --stdout):\n"
         "  --serial DEV       stream binary track messages, accept commands (8N1 raw)\n"
         "  --baud N           9600 19200 38400 57600 115200 (default) 230400 460800 500000\n"
         "                     576000 921600\n"
         "  --protocol P       on --serial: cuetrack (default, docs/serial-protocol.md) or\n"
         "                     mavlink (MAVLink 2 camera component, docs/mavlink.md)\n"
         "  --mavlink-sysid N  our MAVLink system id, 1..255 (default 1, the vehicle's)\n"
         "  --mavlink-compid N our MAVLink component id, 1..255 (default 100, CAMERA)\n"
         "  --mavlink-mount R,P,Y\n"
         "                     camera roll, pitch, yaw on the vehicle [deg] (default 0,0,0:\n"
         "                     looking forward; 0,-90,0: looking down, image top forward)\n"
         "  --mavlink-offset X,Y,Z\n"
         "                     camera position on the vehicle, body frame FRD [m]\n"
         "  --mavlink-udp HOST:PORT\n"
         "                     MAVLink over UDP to HOST:PORT (a MAVLink router on a companion\n"
         "                     computer) instead of --serial; commands from that peer only\n"
         "  --mavlink-key FILE MAVLink 2 signing with the 32-byte key in FILE (chmod 600): our\n"
         "                     messages signed; unsigned, badly signed or replayed commands\n"
         "                     refused and counted. Without it the link is unauthenticated: it\n"
         "                     trusts its network (anyone who can send to it, or forge a\n"
         "                     system id, can command it; docs/mavlink.md)\n"
         "  --mavlink-accept-sysid N[,N...]\n"
         "                     obey commands only from these MAVLink system ids (the\n"
         "                     autopilot's, the ground station's); others are refused and\n"
         "                     counted (default: from any system on the link)\n"
         "  --mavlink-landing frd|angles\n"
         "                     LANDING_TARGET with x,y,z in MAV_FRAME_BODY_FRD (default, for\n"
         "                     ArduPilot) or angles and distance only (for PX4)\n"
         "  --out FILE         CSV, one row per frame ('-' = stdout)\n"
         "  --stdout           one line per frame on stdout as well\n"
         "run:\n"
         "  --frames N         stop after N frames (a synthetic scene then lasts N frames)\n"
         "  --realtime         play a recording or synthetic scene at its own frame rate (its\n"
         "                     timestamps), as the camera would; default: as fast as it tracks\n"
         "  --wait-camera      with --source kinect: no Kinect plugged in yet is not an error;\n"
         "                     look for one every second until it comes (with --serial,\n"
         "                     HEARTBEATs flagged no-camera go out and commands are answered)\n"
         "  --skip-bad-frames  skip a recording's damaged or unreadable frames (counted in the\n"
         "                     final line) instead of stopping on the first\n"
         "  --config NAME      tracker preset: best (default), 1.1-1.4, 2.1-2.5\n"
         "  --seed N           random seed (default 1)\n"
         "  --quiet            no status line (fps, dropped frames, state) on stderr; at the\n"
         "                     end only losses are reported (damaged frames skipped,\n"
         "                     serial messages dropped)\n"
         "  --help\n"
         "exit codes: 0 done (end of source, --frames, SIGINT/SIGTERM/SIGHUP, STOP command),\n"
         "  1 source failed (cannot open, a read failed, a damaged frame, no decodable frame\n"
         "  at all, or a frame's size differs from the frame the track began on), 2 bad\n"
         "  command line (an option given twice too; --show or --select without a display, a\n"
         "  --select cancelled; an output (--out, --video, --snapshot) that is the source, lies\n"
         "  inside its folder, or is another output), 3 output failed (cannot open, a write\n"
         "  to --out/stdout/--video/--snapshot failed, or --video does not read back whole;\n"
         "  tracking went on), 4 the --box, or the source's ground-truth box, refused by the\n"
         "  tracker\n";
}

ParseResult parseOptions(int argc, char** argv, AppOptions* out, char* err, size_t errLen) {
  *out = AppOptions{};
  platform::OptionOnce once;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (a[0] == '-' && !once.first(a, err, errLen)) return ParseResult::Error;
    auto value = [&](const char** v) {
      if (i + 1 >= argc) {
        std::snprintf(err, errLen, "%s needs a value (see --help)", a);
        return false;
      }
      *v = argv[++i];
      return true;
    };
    const char* v = nullptr;
    long n = 0;
    if (std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0) return ParseResult::Help;
    if (std::strcmp(a, "--no-gt") == 0) {
      out->useGroundTruth = false;
    } else if (std::strcmp(a, "--stdout") == 0) {
      out->forceStdout = true;
    } else if (std::strcmp(a, "--quiet") == 0) {
      out->quiet = true;
    } else if (std::strcmp(a, "--realtime") == 0) {
      out->realtime = true;
    } else if (std::strcmp(a, "--wait-camera") == 0) {
      out->waitCamera = true;
    } else if (std::strcmp(a, "--show") == 0) {
      out->show = true;
    } else if (std::strcmp(a, "--select") == 0) {
      out->select = true;
    } else if (std::strcmp(a, "--video") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->videoPath = v;
    } else if (std::strcmp(a, "--snapshot") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->snapshotPath = v;
    } else if (std::strcmp(a, "--skip-bad-frames") == 0) {
      out->skipBadFrames = true;
    } else if (std::strcmp(a, "--source") == 0) {
      if (!value(&v)) return ParseResult::Error;
      // kinect:MODE: the tracker needs colour, so both streams or colour alone.
      if (std::strncmp(v, "kinect:", 7) == 0 && std::strcmp(v + 7, "colour") != 0 &&
          std::strcmp(v + 7, "both") != 0) {
        std::snprintf(err, errLen,
                      "--source %s: expected kinect, kinect:both or kinect:colour (the tracker "
                      "needs colour)",
                      v);
        return ParseResult::Error;
      }
      out->source = v;
    } else if (std::strcmp(a, "--box") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseBox(v, &out->box)) {
        std::snprintf(err, errLen,
                      "--box %s: expected X,Y,W,H [px], finite, W,H > 0, none beyond 100000", v);
        return ParseResult::Error;
      }
      out->hasBox = true;
    } else if (std::strcmp(a, "--serial") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->serialPath = v;
    } else if (std::strcmp(a, "--baud") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseLong(v, LONG_MIN, LONG_MAX, &n)) {
        std::snprintf(err, errLen, "--baud %s: not a number", v);
        return ParseResult::Error;
      }
      if (n < 1 || n > 4000000) {
        std::snprintf(err, errLen, "--baud %s: unsupported (9600..921600, see --help)", v);
        return ParseResult::Error;
      }
      out->baud = static_cast<int>(n);
    } else if (std::strcmp(a, "--protocol") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (std::strcmp(v, "cuetrack") == 0) {
        out->protocol = Protocol::Cuetrack;
      } else if (std::strcmp(v, "mavlink") == 0) {
        out->protocol = Protocol::Mavlink;
      } else {
        std::snprintf(err, errLen, "--protocol %s: expected cuetrack or mavlink", v);
        return ParseResult::Error;
      }
    } else if (std::strcmp(a, "--mavlink-sysid") == 0 || std::strcmp(a, "--mavlink-compid") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseLong(v, 1, 255, &n)) {
        std::snprintf(err, errLen, "%s %s: expected an id 1..255", a, v);
        return ParseResult::Error;
      }
      (std::strcmp(a, "--mavlink-sysid") == 0 ? out->mavSysId : out->mavCompId) =
          static_cast<int>(n);
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-accept-sysid") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseSysIds(v, out->acceptSysIds, AppOptions::kMaxAcceptSysIds,
                       &out->acceptSysIdCount)) {
        std::snprintf(err, errLen,
                      "--mavlink-accept-sysid %s: expected system ids 1..255, comma-separated, "
                      "at most %d",
                      v, AppOptions::kMaxAcceptSysIds);
        return ParseResult::Error;
      }
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-key") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->mavlinkKey = v;
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-mount") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseFloats(v, 3, 360.f, out->mountDeg)) {
        std::snprintf(err, errLen,
                      "--mavlink-mount %s: expected ROLL,PITCH,YAW [deg], each within +-360", v);
        return ParseResult::Error;
      }
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-udp") == 0) {
      if (!value(&v)) return ParseResult::Error;
      char host[256];
      unsigned port = 0;
      if (!platform::splitHostPort(v, host, sizeof host, &port)) {
        std::snprintf(err, errLen, "--mavlink-udp %s: expected HOST:PORT, port 1..65535", v);
        return ParseResult::Error;
      }
      out->mavlinkUdp = v;
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-landing") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (std::strcmp(v, "frd") != 0 && std::strcmp(v, "angles") != 0) {
        std::snprintf(err, errLen, "--mavlink-landing %s: expected frd or angles", v);
        return ParseResult::Error;
      }
      out->landingPosition = std::strcmp(v, "frd") == 0;
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--mavlink-offset") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseFloats(v, 3, 100.f, out->mountOffsetM)) {
        std::snprintf(err, errLen, "--mavlink-offset %s: expected X,Y,Z [m], each within +-100", v);
        return ParseResult::Error;
      }
      if (!out->mavlinkOnlyOption) out->mavlinkOnlyOption = a;
    } else if (std::strcmp(a, "--out") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->outPath = v;
    } else if (std::strcmp(a, "--frames") == 0) {
      if (!value(&v)) return ParseResult::Error;
      if (!parseLong(v, 1, 2000000000L, &n)) {  // 0 would run nothing and say "done"
        std::snprintf(err, errLen, "--frames %s: expected a count >= 1", v);
        return ParseResult::Error;
      }
      out->frames = static_cast<int>(n);
    } else if (std::strcmp(a, "--config") == 0) {
      if (!value(&v)) return ParseResult::Error;
      out->preset = v;
    } else if (std::strcmp(a, "--seed") == 0) {
      if (!value(&v)) return ParseResult::Error;
      char* end = nullptr;
      errno = 0;
      const unsigned long long s = std::strtoull(v, &end, 10);
      // strtoull takes "-1" as 2^64-1: only plain digits are a seed.
      if (*v < '0' || *v > '9' || end == v || *end != '\0' || errno != 0) {
        std::snprintf(err, errLen, "--seed %s: expected a non-negative integer", v);
        return ParseResult::Error;
      }
      out->seed = s;
    } else {
      std::snprintf(err, errLen, "unknown option '%s' (see --help)", a);
      return ParseResult::Error;
    }
  }
  // Only a camera can appear later; a file or a scene that is missing stays missing.
  if (out->waitCamera &&
      (out->source == nullptr ||
       (std::strcmp(out->source, "kinect") != 0 && std::strncmp(out->source, "kinect:", 7) != 0))) {
    std::snprintf(err, errLen, "--wait-camera needs --source kinect or kinect:colour");
    return ParseResult::Error;
  }
  if (out->select && out->hasBox) {
    std::snprintf(err, errLen, "--select and --box: one target at a time");
    return ParseResult::Error;
  }
  if (out->snapshotPath && (out->show || out->select || out->videoPath)) {
    std::snprintf(err, errLen,
                  "--snapshot saves a frame and exits: not with --show, --select or --video");
    return ParseResult::Error;
  }
  // A setting that would do nothing is refused rather than ignored.
  if (out->protocol == Protocol::Mavlink && out->serialPath == nullptr &&
      out->mavlinkUdp == nullptr) {
    std::snprintf(err, errLen, "--protocol mavlink needs --serial DEV or --mavlink-udp HOST:PORT");
    return ParseResult::Error;
  }
  if (out->serialPath != nullptr && out->mavlinkUdp != nullptr) {
    std::snprintf(err, errLen, "--serial and --mavlink-udp: one link at a time");
    return ParseResult::Error;
  }
  if (out->mavlinkOnlyOption && out->protocol != Protocol::Mavlink) {
    std::snprintf(err, errLen, "%s needs --protocol mavlink", out->mavlinkOnlyOption);
    return ParseResult::Error;
  }
  return ParseResult::Run;
}

}  // namespace cuetrack::app
