#include "cuetrack/platform/CommandText.hpp"

#include "cuetrack/platform/DecimalText.hpp"

#include <cerrno>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cuetrack::platform {
namespace {

// Parses exactly `count` comma-separated integers in [lo, hi] covering all of s.
bool parseInts(const char* s, long* out, int count, long lo, long hi) {
  for (int i = 0; i < count; ++i) {
    if (!plainDecimal(s, false, ',')) return false;
    char* end = nullptr;
    errno = 0;
    const long v = std::strtol(s, &end, 10);
    if (end == s || errno != 0 || v < lo || v > hi) return false;
    out[i] = v;
    s = end;
    if (i + 1 < count) {
      if (*s != ',') return false;
      ++s;
    }
  }
  return *s == '\0';
}

// Matches "name" exactly, or "name:" / "name=" followed by arguments (returned).
bool matchVerb(const char* text, const char* verb, const char** args) {
  const size_t n = std::strlen(verb);
  if (std::strncmp(text, verb, n) != 0) return false;
  if (text[n] == '\0') {
    *args = nullptr;
    return true;
  }
  if (text[n] == ':' || text[n] == '=') {
    *args = text + n + 1;
    return true;
  }
  return false;
}

}  // namespace

bool parseCommandText(const char* text, uint16_t id, ctp_command_t* out, char* err, size_t errLen) {
  *out = ctp_command_t{};
  out->id = id;
  const char* args = nullptr;
  if (matchVerb(text, "start", &args)) {
    long v[4];
    if (!args || !parseInts(args, v, 4, -32768, 32767) || v[2] <= 0 || v[3] <= 0) {
      std::snprintf(err, errLen, "command '%s': expected start:X,Y,W,H with W,H > 0 [px]", text);
      return false;
    }
    out->type = CTP_CMD_START;
    for (int i = 0; i < 4; ++i) out->box_px[i] = static_cast<int16_t>(v[i]);
    return true;
  }
  if (matchVerb(text, "rate", &args)) {
    long v = 0;
    if (!args || !parseInts(args, &v, 1, 0, 1000)) {
      std::snprintf(err, errLen,
                    "command '%s': expected rate:HZ with HZ in 0..1000 (0 = every frame)", text);
      return false;
    }
    out->type = CTP_CMD_SET_RATE;
    out->rate_hz = static_cast<uint16_t>(v);
    return true;
  }
  if (matchVerb(text, "reset", &args) && !args) {
    out->type = CTP_CMD_RESET;
    return true;
  }
  if (matchVerb(text, "stop", &args) && !args) {
    out->type = CTP_CMD_STOP;
    return true;
  }
  std::snprintf(err, errLen, "command '%s': unknown (use start:X,Y,W,H, reset, stop or rate:HZ)",
                text);
  return false;
}

size_t formatCommandText(const ctp_command_t& c, char* buf, size_t cap) {
  int n = -1;
  switch (c.type) {
    case CTP_CMD_START:
      n = std::snprintf(buf, cap, "start:%d,%d,%d,%d", c.box_px[0], c.box_px[1], c.box_px[2],
                        c.box_px[3]);
      break;
    case CTP_CMD_SET_RATE:
      n = std::snprintf(buf, cap, "rate:%u", static_cast<unsigned>(c.rate_hz));
      break;
    case CTP_CMD_RESET:
      n = std::snprintf(buf, cap, "reset");
      break;
    case CTP_CMD_STOP:
      n = std::snprintf(buf, cap, "stop");
      break;
    default:
      n = std::snprintf(buf, cap, "unknown");
      break;
  }
  return (n < 0 || static_cast<size_t>(n) >= cap) ? 0 : static_cast<size_t>(n);
}

}  // namespace cuetrack::platform
