#include "RecordOptions.hpp"
#include "cuetrack/platform/DecimalText.hpp"
#include "cuetrack/platform/OptionOnce.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace cuetrack::record {

namespace {

bool parseInt(const char* s, long lo, long hi, long* out) {
  if (!s || !cuetrack::platform::plainDecimal(s, false)) return false;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (errno != 0 || *end != '\0' || v < lo || v > hi) return false;
  *out = v;
  return true;
}

bool parseDouble(const char* s, double lo, double hi, double* out) {
  if (!s || !cuetrack::platform::plainDecimal(s, true)) return false;  // no hex, no 1e3
  char* end = nullptr;
  errno = 0;
  const double v = std::strtod(s, &end);
  if (errno != 0 || *end != '\0' || !(v >= lo && v <= hi)) return false;
  *out = v;
  return true;
}

}  // namespace

void usage(std::FILE* to) {
  std::fprintf(
      to,
      "usage: cuetrack-record --out DIR [--frames N | --seconds S] [options]\n"
      "       cuetrack-record --list\n"
      "\n"
      "Records a Kinect v1 (colour 640x480 + depth, 30 Hz) as a fakenect recording:\n"
      "DIR/INDEX.txt, r-*.ppm colour, d-*.pgm raw 11-bit depth. Replay it with\n"
      "cuetrack --source DIR, or through libfreenect's fakenect (docs/kinect.md).\n"
      "\n"
      "  --out DIR            output folder (created; must not hold a recording)\n"
      "  --format fakenect|rgbd\n"
      "                       fakenect (default), or an RGB-D folder: rgb/ PNG colour,\n"
      "                       depth/ 16-bit PNG mm, intrinsics.txt (docs/recordings.md)\n"
      "  --frames N           stop after N frames\n"
      "  --seconds S          stop after S seconds (camera time)\n"
      "  --device I           Kinect number I (0-based, default 0)\n"
      "  --serial SERIAL      the Kinect with this camera serial (see --list)\n"
      "  --streams both|depth|colour\n"
      "                       both: 21.9 MB/s of USB; depth 12.7; colour 9.2. Pi-class\n"
      "                       boards carry ~15-20 MB/s: use depth or colour there\n"
      "  --depth auto|registered|raw\n"
      "                       registered: mm aligned to colour by libfreenect (auto on\n"
      "                       a device); raw: 11-bit, converted in software (fakenect)\n"
      "  --rate-divisor N     keep every Nth frame (less CPU and disk; USB load unchanged)\n"
      "  --tilt DEG           set the tilt motor, -27..27 degrees\n"
      "  --led off|green|red|yellow|blink-green|blink-red-yellow\n"
      "  --list               print the Kinects found (count and serials) and exit\n"
      "  --quiet              no progress line\n"
      "  --help               this text\n"
      "\n"
      "Stops at the limit, on SIGINT/SIGTERM/SIGHUP (Ctrl-C), or at the end of a fakenect\n"
      "replay;\n"
      "the progress line on stderr shows frames, seconds, dropped and unpaired frames.\n"
      "\n"
      "Exit codes: 0 recorded (limit, signal or end of replay), 1 no Kinect / cannot open\n"
      "it / stream failed (unplugged, no frames), 2 bad command line (an option given twice\n"
      "too), 3 cannot write.\n");
}

ParseResult parse(int argc, char** argv, Options* out, char* err, std::size_t errLen) {
  Options o;
  auto bad = [&](const char* what, const char* arg) {
    std::snprintf(err, errLen, "%s: '%s'", what, arg ? arg : "");
    return ParseResult::Error;
  };
  platform::OptionOnce once;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    if (a[0] == '-' && !once.first(a, err, errLen)) return ParseResult::Error;
    const char* v = i + 1 < argc ? argv[i + 1] : nullptr;
    auto needValue = [&]() {
      if (!v) std::snprintf(err, errLen, "%s needs a value", a);
      return v != nullptr;
    };
    long n = 0;
    if (std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0) {
      return ParseResult::Help;
    } else if (std::strcmp(a, "--list") == 0) {
      o.list = true;
    } else if (std::strcmp(a, "--quiet") == 0) {
      o.quiet = true;
    } else if (std::strcmp(a, "--out") == 0) {
      if (!needValue()) return ParseResult::Error;
      o.outDir = v;
      ++i;
    } else if (std::strcmp(a, "--format") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (std::strcmp(v, "fakenect") == 0)
        o.format = Format::Fakenect;
      else if (std::strcmp(v, "rgbd") == 0)
        o.format = Format::Rgbd;
      else
        return bad("--format takes fakenect or rgbd", v);
      ++i;
    } else if (std::strcmp(a, "--frames") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseInt(v, 1, 100000000, &n)) return bad("--frames needs a count >= 1", v);
      o.maxFrames = static_cast<int>(n);
      ++i;
    } else if (std::strcmp(a, "--seconds") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseDouble(v, 0.001, 1e7, &o.maxSeconds))
        return bad("--seconds needs a duration > 0", v);
      ++i;
    } else if (std::strcmp(a, "--device") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseInt(v, 0, 63, &n)) return bad("--device needs an index 0..63", v);
      o.kinect.deviceIndex = static_cast<int>(n);
      ++i;
    } else if (std::strcmp(a, "--serial") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!*v) return bad("--serial needs a serial", v);
      o.kinect.serial = v;
      ++i;
    } else if (std::strcmp(a, "--streams") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseKinectStreams(v, &o.kinect.streams))
        return bad("--streams takes both, depth or colour", v);
      ++i;
    } else if (std::strcmp(a, "--depth") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseKinectDepthMode(v, &o.kinect.depthMode))
        return bad("--depth takes auto, registered or raw", v);
      ++i;
    } else if (std::strcmp(a, "--rate-divisor") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseInt(v, 1, 30, &n)) return bad("--rate-divisor needs 1..30", v);
      o.kinect.rateDivisor = static_cast<int>(n);
      ++i;
    } else if (std::strcmp(a, "--tilt") == 0) {
      if (!needValue()) return ParseResult::Error;
      double deg = 0;
      if (!parseDouble(v, -27.0, 27.0, &deg)) return bad("--tilt needs degrees in -27..27", v);
      o.kinect.setTilt = true;
      o.kinect.tiltDeg = static_cast<float>(deg);
      ++i;
    } else if (std::strcmp(a, "--led") == 0) {
      if (!needValue()) return ParseResult::Error;
      if (!parseKinectLed(v, &o.kinect.led))
        return bad("--led takes off, green, red, yellow, blink-green or blink-red-yellow", v);
      ++i;
    } else {
      return bad("unknown argument", a);
    }
  }
  if (!o.list && !o.outDir) {
    std::snprintf(err, errLen, "--out DIR is required");
    return ParseResult::Error;
  }
  if (o.maxFrames > 0 && o.maxSeconds > 0.0) {
    std::snprintf(err, errLen, "give --frames or --seconds, not both");
    return ParseResult::Error;
  }
  *out = o;
  return ParseResult::Ok;
}

}  // namespace cuetrack::record
