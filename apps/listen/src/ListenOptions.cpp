#include "ListenOptions.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cuetrack/platform/CommandText.hpp"
#include "cuetrack/platform/OptionOnce.hpp"

namespace cuetrack::listen {
namespace {

bool parseInt(const char* s, long lo, long hi, long* out) {
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (end == s || *end != '\0' || errno != 0 || v < lo || v > hi) return false;
  *out = v;
  return true;
}

// The rates termios has on Linux (SerialPort::baudSupported, kept here so the parser
// needs no OS code).
bool baudSupported(long b) {
  static const long kBauds[] = {9600,   19200,  38400,  57600,  115200,
                                230400, 460800, 500000, 576000, 921600};
  for (long k : kBauds)
    if (k == b) return true;
  return false;
}

}  // namespace

ListenParse parseListenOptions(int argc, char** argv, ListenOptions* o, char* err, size_t errLen) {
  *o = ListenOptions{};
  platform::OptionOnce once;
  for (int i = 1; i < argc; ++i) {
    const char* a = argv[i];
    const bool hasValue = i + 1 < argc;
    if (a[0] == '-' && std::strcmp(a, "--send") != 0 && !once.first(a, err, errLen))
      return ListenParse::Error;
    if (std::strcmp(a, "--help") == 0 || std::strcmp(a, "-h") == 0) {
      return ListenParse::Help;
    } else if (std::strcmp(a, "--baud") == 0 && hasValue) {
      if (!parseInt(argv[++i], 1, 4000000, &o->baud) || !baudSupported(o->baud)) {
        std::snprintf(err, errLen, "--baud %s: unsupported (9600..921600)", argv[i]);
        return ListenParse::Error;
      }
    } else if (std::strcmp(a, "--csv") == 0 && hasValue) {
      o->csvPath = argv[++i];
    } else if (std::strcmp(a, "--state") == 0 && hasValue) {
      o->statePath = argv[++i];
    } else if (std::strcmp(a, "--reconnect") == 0) {
      o->reconnect = true;
    } else if (std::strcmp(a, "--send") == 0 && hasValue) {
      if (o->numSends >= ListenOptions::kMaxSends) {
        std::snprintf(err, errLen, "too many --send (at most %d)", ListenOptions::kMaxSends);
        return ListenParse::Error;
      }
      o->sends[o->numSends++] = argv[++i];
    } else if (std::strcmp(a, "--tracks") == 0 && hasValue) {
      if (!parseInt(argv[++i], 1, 2000000000L, &o->maxTracks)) {  // 0 would wait for nothing
        std::snprintf(err, errLen, "--tracks %s: expected a count >= 1", argv[i]);
        return ListenParse::Error;
      }
    } else if (std::strcmp(a, "--idle-timeout") == 0 && hasValue) {
      if (!parseInt(argv[++i], 1, 86400, &o->idleS)) {
        std::snprintf(err, errLen, "--idle-timeout %s: expected seconds >= 1", argv[i]);
        return ListenParse::Error;
      }
    } else if (std::strcmp(a, "--wait-port") == 0 && hasValue) {
      if (!parseInt(argv[++i], 0, 86400, &o->waitPortS)) {
        std::snprintf(err, errLen, "--wait-port %s: expected seconds >= 0", argv[i]);
        return ListenParse::Error;
      }
    } else if (a[0] == '-' && a[1] != '\0') {
      std::snprintf(err, errLen, "unknown option or missing value: '%s' (see --help)", a);
      return ListenParse::Error;
    } else if (!o->portPath) {
      o->portPath = a;
    } else {
      std::snprintf(err, errLen, "unexpected argument '%s' (one PORT only)", a);
      return ListenParse::Error;
    }
  }
  if (!o->portPath) {
    std::snprintf(err, errLen, "missing PORT (see --help)");
    return ListenParse::Error;
  }
  // Every command is checked before the port is touched.
  for (int i = 0; i < o->numSends; ++i) {
    if (!platform::parseCommandText(o->sends[i], static_cast<uint16_t>(i + 1), &o->commands[i], err,
                                    errLen))
      return ListenParse::Error;
  }
  return ListenParse::Run;
}

}  // namespace cuetrack::listen
