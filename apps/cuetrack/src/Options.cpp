#include "Options.hpp"

#include <cstdio>
#include <cstring>
#include <vector>

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"

namespace cuetrack::app {
namespace {

const char* kAbout =
    "Tracks an object in RGB-D frames and streams the track (docs/serial-protocol.md,\n"
    "docs/mavlink.md).";

const char* kFooter =
    "--source (default: the Kinect when one is plugged in, else a V4L2 camera, else the\n"
    "  synthetic scene 'moving'): kinect:colour streams colour only: 2D tracking, 9.2\n"
    "  instead of 21.9 MB/s of USB (docs/kinect.md); camera[:N|:/dev/videoN]: a webcam or\n"
    "  USB camera, colour only (host builds with OpenCV); SCENE: one of cuetrack-synth\n"
    "  --list (docs/recordings.md); PATH: a fakenect recording folder (host builds with\n"
    "  OpenCV also read RGB-D, OTB and image folders, videos: .avi .mp4 .mkv .mov ..., and\n"
    "  pan:/still: stills; docs/recordings.md). Frames larger than 640x480 are scaled\n"
    "  down for the tracker; boxes in and out stay in the source's own pixels.\n"
    "target (default: the ground truth where the target first shows, else wait for START;\n"
    "  no ground truth, no --box, --select or link for a START: exit 2, nothing to track).\n"
    "--show and --select need a display and a host build with OpenCV; in the window, space\n"
    "  pauses, r re-selects the target, q or Esc quits.\n"
    "stdout gets one line per frame when neither --serial nor --out is given, and stdout\n"
    "  is not a terminal: there, only with --stdout.\n"
    "--mavlink-mount: 0,0,0 looks forward; 0,-90,0 looks down, image top forward.\n"
    "--mavlink-landing frd: LANDING_TARGET x,y,z in MAV_FRAME_BODY_FRD (ArduPilot);\n"
    "  angles: angles and distance only (PX4).\n"
    "--mavlink-key: without it the link is unauthenticated: it trusts its network (anyone\n"
    "  who can send to it, or forge a system id, can command it; docs/mavlink.md).\n"
    "numbers are plain decimals (12, -0.5, .5): no blanks, hex, exponents, inf or nan.\n"
    "exit codes: 0 done (end of source, --frames, SIGINT/SIGTERM/SIGHUP, STOP command),\n"
    "  1 source failed (cannot open, a read failed, a damaged frame, no decodable frame\n"
    "  at all, or a frame's size differs from the frame the track began on), 2 bad\n"
    "  command line (an option given twice too; an unknown scene; no way to a target;\n"
    "  --show or --select without a display, a --select cancelled; an output (--out,\n"
    "  --video, --snapshot) that is the source, its ground truth or --gt, lies inside its\n"
    "  folder, or is another output, --force or not), 3 output failed\n"
    "  (cannot open, a write to --out/stdout/--video/--snapshot failed, or --video does not\n"
    "  read back whole; tracking went on), 4 the --box, or the source's ground-truth box,\n"
    "  refused by the tracker";

// An id 1..255 (--mavlink-sysid, --mavlink-compid).
cli::Convert mavlinkId(int* out) {
  return [out](const std::string& v) {
    long n = 0;
    if (!cli::wholeNumber(v, 1, 255, &n).empty()) return std::string("expected an id 1..255");
    *out = static_cast<int>(n);
    return std::string();
  };
}

// "N[,N...]": MAVLink system ids 1..255 each (0 is "every system", never a sender), at
// most AppOptions::kMaxAcceptSysIds (--mavlink-accept-sysid).
cli::Convert sysIds(AppOptions* o) {
  return [o](const std::string& v) {
    const std::string why = "expected system ids 1..255, comma-separated, at most " +
                            std::to_string(AppOptions::kMaxAcceptSysIds);
    o->acceptSysIdCount = 0;
    for (size_t start = 0;;) {
      const size_t comma = v.find(',', start);
      const std::string token =
          v.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
      long id = 0;
      if (o->acceptSysIdCount >= AppOptions::kMaxAcceptSysIds ||
          !cli::wholeNumber(token, 1, 255, &id).empty()) {
        o->acceptSysIdCount = 0;
        return why;
      }
      o->acceptSysIds[o->acceptSysIdCount++] = static_cast<int>(id);
      if (comma == std::string::npos) return std::string();
      start = comma + 1;
    }
  };
}

// Three numbers A,B,C, each within +-limit (--mavlink-mount, --mavlink-offset).
cli::Convert three(float limit, float* out, const char* why) {
  return [limit, out, why](const std::string& v) {
    return cli::numbers(v, 3, limit, out).empty() ? std::string() : std::string(why);
  };
}

// A recording read from a path (a video or a folder), whose ground truth is a file.
bool recordingSpec(const char* spec) {
  if (spec == nullptr) return false;
  for (const char* generated : {"kinect", "camera", "synth", "rand:", "pan:", "still:"})
    if (std::strncmp(spec, generated, std::strlen(generated)) == 0) return false;
  return true;
}

// The source, the target and the outputs.
void declareInputsOutputs(cli::Command& cmd, AppOptions* o) {
  AppOptions::Texts& t = o->texts;
  const std::string source = "source", target = "target", see = "see it", outputs = "outputs";
  cmd.option("--source", "kinect[:colour]|camera[:N]|synth[:SCENE]|PATH", "the frames (below)",
             [&t](const std::string& v) {
               // kinect:MODE: the tracker needs colour, so both streams or colour alone.
               if (v.compare(0, 7, "kinect:") == 0 && v != "kinect:colour" && v != "kinect:both")
                 return "expected kinect, kinect:both or kinect:colour (the tracker needs colour)";
               if (v.compare(0, 7, "camera:") == 0 &&
                   (v.size() == 7 ||
                    (v[7] != '/' && v.find_first_not_of("0123456789", 7) != std::string::npos)))
                 return "expected camera, camera:N or camera:/dev/videoN";
               t.source = v;
               return "";
             })
      ->group(source);
  cmd.option("--box", "X,Y,W,H", "target box in the first frame [px]",
             [o](const std::string& v) {
               const std::string why = cli::box(v, &o->box);
               o->hasBox = why.empty();
               return why;
             })
      ->group(target);
  cmd.text("--gt", "FILE",
           "a recording's ground truth under another name (else NAME.gt.txt or NAME.txt beside "
           "a video, a folder's own)",
           &t.gt)
      ->group(target);
  cmd.app()
      .add_flag("--no-gt", "ignore ground truth: wait for --box or a serial START command")
      ->group(target);
  cmd.flag("--select", "drag a box around the target on the first frame; prints it as --box",
           &o->select)
      ->group(target);
  cmd.text("--snapshot", "FILE.png",
           "save the first frame with a 40 px grid and exit, to read a --box off it", &t.snapshot)
      ->group(target);
  cmd.flag("--show", "live window: box, state, confidence, fps, depth beside it", &o->show)
      ->group(see);
  cmd.text("--video", "FILE.avi",
           "every frame with its box, state, confidence and frame number (Motion JPEG)", &t.video)
      ->group(see);
  cmd.text("--serial", "DEV", "stream binary track messages, accept commands (8N1 raw)", &t.serial)
      ->group(outputs);
  cmd.option("--baud", "N",
             "9600 19200 38400 57600 115200 (default) 230400 460800 500000 576000 921600",
             [o](const std::string& v) { return cli::baudRate(v, &o->baud); })
      ->group(outputs);
  cmd.option("--protocol", "P",
             "on --serial: cuetrack (default, docs/serial-protocol.md) or mavlink "
             "(docs/mavlink.md)",
             [o](const std::string& v) {
               if (v != "cuetrack" && v != "mavlink") return "expected cuetrack or mavlink";
               o->protocol = v == "mavlink" ? Protocol::Mavlink : Protocol::Cuetrack;
               return "";
             })
      ->group(outputs);
  cmd.text("--out", "FILE", "CSV, one row per frame ('-' = stdout)", &t.out)->group(outputs);
  cmd.flag("--stdout", "one line per frame on stdout as well", &o->forceStdout)->group(outputs);
}

// MAVLink's options.
void declareMavlink(cli::Command& cmd, AppOptions* o) {
  AppOptions::Texts& t = o->texts;
  const std::string mavlink = "MAVLink (with --protocol mavlink)";
  cmd.option("--mavlink-sysid", "N", "our MAVLink system id, 1..255 (default 1, the vehicle's)",
             mavlinkId(&o->mavSysId))
      ->group(mavlink);
  cmd.option("--mavlink-compid", "N", "our MAVLink component id, 1..255 (default 100, CAMERA)",
             mavlinkId(&o->mavCompId))
      ->group(mavlink);
  cmd.option("--mavlink-mount", "R,P,Y", "camera roll, pitch, yaw on the vehicle [deg]",
             three(360.f, o->mountDeg, "expected ROLL,PITCH,YAW [deg], each within +-360"))
      ->group(mavlink);
  cmd.option("--mavlink-offset", "X,Y,Z", "camera position on the vehicle, body frame FRD [m]",
             three(100.f, o->mountOffsetM, "expected X,Y,Z [m], each within +-100"))
      ->group(mavlink);
  cmd.option("--mavlink-udp", "HOST:PORT",
             "MAVLink over UDP (a MAVLink router on a companion computer) instead of --serial; "
             "commands from that peer only",
             [&t](const std::string& v) {
               t.mavlinkUdp = v;
               return cli::hostPort(v);
             })
      ->group(mavlink);
  cmd.text("--mavlink-key", "FILE",
           "MAVLink 2 signing with the 32-byte key in FILE (chmod 600): our messages signed; "
           "unsigned, badly signed or replayed commands refused and counted (below)",
           &t.mavlinkKey)
      ->group(mavlink);
  cmd.option("--mavlink-accept-sysid", "N[,N...]",
             "obey commands only from these MAVLink system ids (the autopilot's, the ground "
             "station's); others are refused and counted (default: from any system on the link)",
             sysIds(o))
      ->group(mavlink);
  cmd.option("--mavlink-rate", "BYTES_PER_S",
             "MAVLink output rate: answers wait for it, telemetry beyond it is dropped and "
             "counted (default: --baud / 10 on --serial, 100000 over UDP)",
             [o](const std::string& v) {
               return cli::wholeNumber(v, 100, 100000000, &o->mavlinkRateBytesPerS).empty()
                          ? ""
                          : "expected bytes a second, 100..100000000";
             })
      ->group(mavlink);
  cmd.option("--mavlink-landing", "frd|angles", "LANDING_TARGET's form (below; default frd)",
             [o](const std::string& v) {
               if (v != "frd" && v != "angles") return "expected frd or angles";
               o->landingPosition = v == "frd";
               return "";
             })
      ->group(mavlink);
}

// How the run goes.
void declareRun(cli::Command& cmd, AppOptions* o) {
  AppOptions::Texts& t = o->texts;
  const std::string run = "run";
  cmd.option("--frames", "N", "stop after N frames (a synthetic scene then lasts N frames)",
             [o](const std::string& v) {
               long n = 0;  // 0 would run nothing and say "done"
               if (!cli::wholeNumber(v, 1, 2000000000L, &n).empty()) return "expected a count >= 1";
               o->frames = static_cast<int>(n);
               return "";
             })
      ->group(run);
  cmd.flag("--realtime", "play a recording or scene at its own frame rate, as the camera would",
           &o->realtime)
      ->group(run);
  cmd.flag("--wait-camera",
           "with --source kinect: wait for a Kinect to be plugged in (heartbeats meanwhile)",
           &o->waitCamera)
      ->group(run);
  cmd.flag("--skip-bad-frames", "skip a recording's damaged frames (counted) instead of stopping",
           &o->skipBadFrames)
      ->group(run);
  cmd.text("--config", "NAME", "tracker preset: best (default), dcf, 1.1-1.4, 2.1-2.5", &t.preset)
      ->group(run);
  cmd.option("--seed", "N", "random seed (default 1)",
             [o](const std::string& v) {
               return cli::seed(v, &o->seed).empty() ? "" : "expected a non-negative integer";
             })
      ->group(run);
  cmd.flag("--quiet",
           "no status lines on stderr; at the end only losses (frames not tracked or skipped, "
           "messages dropped)",
           &o->quiet)
      ->group(run);
}

// Every option of cuetrack, into *o (its texts into o->texts), in --help's order.
void declare(cli::Command& cmd, AppOptions* o) {
  declareInputsOutputs(cmd, o);
  declareMavlink(cmd, o);
  declareRun(cmd, o);
}

}  // namespace

std::string usageText() {
  cli::Command cmd("cuetrack", kAbout, kFooter, cli::Quotes::None);
  AppOptions o;
  declare(cmd, &o);
  return cmd.help();
}

ParseResult parseOptions(int argc, char** argv, AppOptions* out, char* err, size_t errLen) {
  *out = AppOptions{};
  cli::Command cmd("cuetrack", kAbout, kFooter, cli::Quotes::None);
  declare(cmd, out);
  const cli::Command::Parsed parsed = cmd.check(argc, argv, err, errLen);
  if (parsed != cli::Command::Parsed::Run)
    return parsed == cli::Command::Parsed::Help ? ParseResult::Help : ParseResult::Error;
  AppOptions::Texts& t = out->texts;
  auto text = [&cmd](const char* name, const std::string& value) {
    return cmd.given(name) ? value.c_str() : nullptr;
  };
  out->source = text("--source", t.source);
  out->serialPath = text("--serial", t.serial);
  out->outPath = text("--out", t.out);
  out->mavlinkUdp = text("--mavlink-udp", t.mavlinkUdp);
  out->mavlinkKey = text("--mavlink-key", t.mavlinkKey);
  out->snapshotPath = text("--snapshot", t.snapshot);
  out->videoPath = text("--video", t.video);
  if (cmd.given("--config")) out->preset = t.preset.c_str();
  out->useGroundTruth = !cmd.given("--no-gt");
  out->gtPath = text("--gt", t.gt);
  // The first --mavlink-* option on the command line.
  static const char* const kMavlinkOnly[] = {
      "--mavlink-sysid",        "--mavlink-compid",  "--mavlink-mount",
      "--mavlink-offset",       "--mavlink-udp",     "--mavlink-key",
      "--mavlink-accept-sysid", "--mavlink-landing", "--mavlink-rate"};
  for (const CLI::Option* opt : cmd.app().parse_order()) {
    for (const char* name : kMavlinkOnly)
      if (!out->mavlinkOnlyOption && opt->get_name() == name) out->mavlinkOnlyOption = name;
  }
  auto fail = [&](const std::string& line) {
    std::snprintf(err, errLen, "%s", line.c_str());
    return ParseResult::Error;
  };
  // Only a camera can appear later; a file or a scene that is missing stays missing.
  if (out->waitCamera && (out->source == nullptr || (std::strcmp(out->source, "kinect") != 0 &&
                                                     std::strncmp(out->source, "kinect:", 7) != 0)))
    return fail("--wait-camera needs --source kinect or kinect:colour");
  if (out->select && out->hasBox) return fail("--select and --box: one target at a time");
  if (out->gtPath && !out->useGroundTruth) return fail("--gt and --no-gt: one or the other");
  if (out->gtPath && !recordingSpec(out->source))
    return fail(std::string("--gt: ") + (out->source ? out->source : "the default source") +
                " has no ground-truth file (--gt is for a recording: a video or a folder)");
  if (out->snapshotPath && (out->show || out->select || out->videoPath))
    return fail("--snapshot saves a frame and exits: not with --show, --select or --video");
  // A setting that would do nothing is refused rather than ignored.
  if (out->protocol == Protocol::Mavlink && out->serialPath == nullptr &&
      out->mavlinkUdp == nullptr)
    return fail("--protocol mavlink needs --serial DEV or --mavlink-udp HOST:PORT");
  if (out->serialPath != nullptr && out->mavlinkUdp != nullptr)
    return fail("--serial and --mavlink-udp: one link at a time");
  if (out->mavlinkOnlyOption && out->protocol != Protocol::Mavlink)
    return fail(std::string(out->mavlinkOnlyOption) + " needs --protocol mavlink");
  return ParseResult::Run;
}

}  // namespace cuetrack::app
