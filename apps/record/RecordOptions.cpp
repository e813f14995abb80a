#include "RecordOptions.hpp"

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"

namespace cuetrack::record {

namespace {

// A number in [lo, hi], else `want` as the reason.
std::string decimal(const std::string& text, double lo, double hi, const char* want, double* out) {
  return cli::decimal(text, lo, hi, out).empty() ? std::string() : std::string(want);
}

const char* kAbout =
    "usage: cuetrack-record --out DIR [--frames N | --seconds S] [options]\n"
    "       cuetrack-record --list\n"
    "\n"
    "Records a Kinect v1 (colour 640x480 + depth, 30 Hz) as a fakenect recording:\n"
    "DIR/INDEX.txt, r-*.ppm colour, d-*.pgm raw 11-bit depth. Replay it with\n"
    "cuetrack --source DIR, or through libfreenect's fakenect (docs/kinect.md).\n";

const char* kFooter =
    "--streams both: 21.9 MB/s of USB; depth 12.7; colour 9.2. Pi-class boards carry\n"
    "~15-20 MB/s: use depth or colour there. --depth registered: mm aligned to colour by\n"
    "libfreenect (auto on a device); raw: 11-bit, converted in software (fakenect).\n"
    "\n"
    "Stops at the limit, on SIGINT/SIGTERM/SIGHUP (Ctrl-C), or at the end of a fakenect\n"
    "replay; the progress line on stderr shows frames, seconds, dropped and unpaired frames.\n"
    "\n"
    "Exit codes: 0 recorded (limit, signal or end of replay), 1 no Kinect / cannot open\n"
    "it / stream failed (unplugged, no frames), 2 bad command line (an option given twice\n"
    "too), 3 cannot write.";

}  // namespace

int parse(int argc, const char* const* argv, Options* out) {
  Options& o = *out;
  o = Options{};
  cli::Command cmd("cuetrack-record", kAbout, kFooter);
  cmd.text("--out", "DIR", "output folder (created; must not hold a recording)", &o.outDir);
  cmd.option("--format", "fakenect|rgbd",
             "fakenect (default) or rgbd: rgb/ PNG, depth/ 16-bit PNG mm (docs/recordings.md)",
             [&o](const std::string& v) {
               int k = 0;
               const std::string why = cli::oneOf(v, "fakenect|rgbd", &k);
               o.format = k == 0 ? Format::Fakenect : Format::Rgbd;
               return why;
             });
  cmd.option("--frames", "N", "stop after N frames", [&o](const std::string& v) {
    long n = 0;
    if (!cli::wholeNumber(v, 1, 100000000, &n).empty()) return "expected a count >= 1";
    o.maxFrames = static_cast<int>(n);
    return "";
  });
  cmd.option("--seconds", "S", "stop after S seconds (camera time)", [&o](const std::string& v) {
    return decimal(v, 0.001, 1e7, "expected a duration > 0", &o.maxSeconds);
  });
  cmd.number("--device", "I", "Kinect number I (0-based, default 0)", 0, 63, &o.kinect.deviceIndex);
  cmd.option("--serial", "SERIAL", "the Kinect with this camera serial (see --list)",
             [&o](const std::string& v) {
               o.serial = v;
               return v.empty() ? "expected a serial" : "";
             });
  cmd.option(
      "--streams", "both|depth|colour", "what to stream (below)", [&o](const std::string& v) {
        return parseKinectStreams(v.c_str(), &o.kinect.streams) ? ""
                                                                : "expected both, depth or colour";
      });
  cmd.option("--depth", "auto|registered|raw", "depth as mm or raw (below)",
             [&o](const std::string& v) {
               return parseKinectDepthMode(v.c_str(), &o.kinect.depthMode)
                          ? ""
                          : "expected auto, registered or raw";
             });
  cmd.number("--rate-divisor", "N",
             "keep every Nth frame, 1..30 (less CPU and disk; USB load "
             "unchanged)",
             1, 30, &o.kinect.rateDivisor);
  cmd.option("--tilt", "DEG", "set the tilt motor, -27..27 degrees", [&o](const std::string& v) {
    double deg = 0;
    const std::string why = decimal(v, -27.0, 27.0, "expected degrees in -27..27", &deg);
    o.kinect.setTilt = why.empty();
    o.kinect.tiltDeg = static_cast<float>(deg);
    return why;
  });
  cmd.option("--led", "off|green|red|yellow|blink-green|blink-red-yellow", "the LED",
             [&o](const std::string& v) {
               return parseKinectLed(v.c_str(), &o.kinect.led)
                          ? ""
                          : "expected off, green, red, yellow, blink-green or blink-red-yellow";
             });
  cmd.flag("--list", "print the Kinects found (count and serials) and exit", &o.list);
  cmd.flag("--quiet", "no progress line", &o.quiet);
  const int rc = cmd.parse(argc, argv);
  if (rc >= 0) return rc == 0 ? kExitOk : rc == kExitUsage ? kExitUsage : kExitOutput;
  if (!o.serial.empty()) o.kinect.serial = o.serial.c_str();
  if (!o.list && o.outDir.empty()) return cmd.fail("--out DIR is required (see --help)");
  if (o.maxFrames > 0 && o.maxSeconds > 0.0)
    return cmd.fail("give --frames or --seconds, not both (see --help)");
  return -1;
}

}  // namespace cuetrack::record
