#include "cuetrack/drivers/RecordedParsers.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#include "cuetrack/core/config/Config.hpp"

namespace cuetrack::rec {

namespace {

void fail(char* err, size_t errLen, const char* fmt, ...) {
  if (!err || errLen == 0) return;
  va_list ap;
  va_start(ap, fmt);
  std::vsnprintf(err, errLen, fmt, ap);
  va_end(ap);
}

bool isSpace(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n' || c == '\v' || c == '\f';
}

// Copies a line into a NUL-terminated local buffer (strtod needs one).
bool copyLine(const char* line, size_t len, char* buf, size_t bufLen, char* err, size_t errLen) {
  if (len >= bufLen) {
    fail(err, errLen, "line longer than %zu characters", bufLen - 1);
    return false;
  }
  std::memcpy(buf, line, len);
  buf[len] = '\0';
  return true;
}

// Parses up to n floats separated by whitespace and/or commas; exactly n required.
bool parseFloats(const char* s, float* out, int n, bool allowCommas, char* err, size_t errLen) {
  const char* p = s;
  for (int i = 0; i < n; ++i) {
    while (isSpace(*p) || (allowCommas && *p == ',' && i > 0)) ++p;
    char* end = nullptr;
    const double v = std::strtod(p, &end);
    if (end == p) {
      fail(err, errLen, "expected %d numbers, found %d", n, i);
      return false;
    }
    if (!std::isfinite(v) || std::fabs(v) > 1e7) {
      fail(err, errLen, "number %d out of range", i + 1);
      return false;
    }
    out[i] = static_cast<float>(v);
    p = end;
    // Separator required between numbers.
    if (i + 1 < n && !(isSpace(*p) || (allowCommas && *p == ','))) {
      if (*p == '\0')
        fail(err, errLen, "expected %d numbers, found %d", n, i + 1);
      else if (*p > ' ' && *p < 127)
        fail(err, errLen, "unexpected character '%c' after number %d", *p, i + 1);
      else
        fail(err, errLen, "unexpected byte 0x%02x after number %d",
             static_cast<unsigned>(static_cast<unsigned char>(*p)), i + 1);
      return false;
    }
  }
  while (isSpace(*p) || (allowCommas && *p == ',')) ++p;
  if (*p != '\0') {
    fail(err, errLen, "trailing characters after %d numbers", n);
    return false;
  }
  return true;
}

// PNM header token: skips whitespace and '#' comments, reads a decimal number.
bool pnmNumber(const uint8_t* buf, size_t len, size_t* pos, int* out) {
  size_t p = *pos;
  for (;;) {
    while (p < len && isSpace(static_cast<char>(buf[p]))) ++p;
    if (p < len && buf[p] == '#') {
      while (p < len && buf[p] != '\n') ++p;
      continue;
    }
    break;
  }
  if (p >= len || buf[p] < '0' || buf[p] > '9') return false;
  long v = 0;
  while (p < len && buf[p] >= '0' && buf[p] <= '9') {
    v = v * 10 + (buf[p] - '0');
    if (v > 1000000) return false;
    ++p;
  }
  *out = static_cast<int>(v);
  *pos = p;
  return true;
}

}  // namespace

bool parsePnmHeader(const uint8_t* buf, size_t len, PnmHeader* out, char* err, size_t errLen) {
  PnmHeader h;
  if (!parsePnmHeaderPrefix(buf, len, &h, err, errLen)) return false;
  if (len - h.dataOffset < h.dataBytes()) {
    fail(err, errLen, "truncated: %zu of %zu pixel bytes", len - h.dataOffset, h.dataBytes());
    return false;
  }
  *out = h;
  return true;
}

bool parsePnmHeaderPrefix(const uint8_t* buf, size_t len, PnmHeader* out, char* err,
                          size_t errLen) {
  if (len < 2 || buf[0] != 'P' || (buf[1] != '5' && buf[1] != '6')) {
    fail(err, errLen, "not a binary PGM/PPM (no P5/P6 magic)");
    return false;
  }
  PnmHeader h;
  h.type = static_cast<char>(buf[1]);
  size_t p = 2;
  if (!pnmNumber(buf, len, &p, &h.width) || !pnmNumber(buf, len, &p, &h.height) ||
      !pnmNumber(buf, len, &p, &h.maxval)) {
    fail(err, errLen, "truncated or malformed PNM header");
    return false;
  }
  // Exactly one whitespace byte ends the header.
  if (p >= len || !isSpace(static_cast<char>(buf[p]))) {
    fail(err, errLen, "PNM header not followed by whitespace");
    return false;
  }
  ++p;
  if (h.width <= 0 || h.height <= 0 || h.width > kMaxImageWidth || h.height > kMaxImageHeight) {
    fail(err, errLen, "image size %dx%d outside 1x1..%dx%d", h.width, h.height, kMaxImageWidth,
         kMaxImageHeight);
    return false;
  }
  if (h.maxval < 1 || h.maxval > 65535) {
    fail(err, errLen, "PNM maxval %d outside 1..65535", h.maxval);
    return false;
  }
  h.dataOffset = p;
  *out = h;
  return true;
}

bool decodePnmRgb(const uint8_t* buf, size_t len, const PnmHeader& h, Rgb8* dst, char* err,
                  size_t errLen) {
  if (h.bytesPerSample() != 1) {
    fail(err, errLen, "colour image with 16-bit samples (maxval %d) not supported", h.maxval);
    return false;
  }
  if (h.dataOffset > len || len - h.dataOffset < h.dataBytes()) {
    fail(err, errLen, "truncated pixel data");
    return false;
  }
  const uint8_t* src = buf + h.dataOffset;
  const size_t n = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  if (h.type == '6') {
    std::memcpy(static_cast<void*>(dst), src, n * 3);
  } else {
    for (size_t i = 0; i < n; ++i) dst[i] = {src[i], src[i], src[i]};
  }
  return true;
}

bool decodePnm16(const uint8_t* buf, size_t len, const PnmHeader& h, Endian endian, uint16_t* dst,
                 char* err, size_t errLen) {
  if (h.type != '5' || h.bytesPerSample() != 2) {
    fail(err, errLen, "expected a 16-bit P5 depth image (got P%c, maxval %d)", h.type, h.maxval);
    return false;
  }
  if (h.dataOffset > len || len - h.dataOffset < h.dataBytes()) {
    fail(err, errLen, "truncated pixel data");
    return false;
  }
  const uint8_t* src = buf + h.dataOffset;
  const size_t n = static_cast<size_t>(h.width) * static_cast<size_t>(h.height);
  if (endian == Endian::Little) {
    for (size_t i = 0; i < n; ++i)
      dst[i] = static_cast<uint16_t>(src[2 * i] | (src[2 * i + 1] << 8));
  } else {
    for (size_t i = 0; i < n; ++i)
      dst[i] = static_cast<uint16_t>((src[2 * i] << 8) | src[2 * i + 1]);
  }
  return true;
}

bool parseIndexLine(const char* line, size_t len, IndexEntry* out, char* err, size_t errLen) {
  char buf[256];
  if (!copyLine(line, len, buf, sizeof buf, err, errLen)) return false;
  if (!(buf[0] == 'r' || buf[0] == 'd' || buf[0] == 'a') || buf[1] != '-') {
    fail(err, errLen, "INDEX entry '%.60s' is not r-/d-/a-<seconds>-<timestamp>.<ext>", buf);
    return false;
  }
  if (std::strchr(buf, '/') || std::strstr(buf, "..")) {
    fail(err, errLen, "INDEX entry '%.60s' names a path outside the recording", buf);
    return false;
  }
  char* end = nullptr;
  const double sec = std::strtod(buf + 2, &end);
  if (end == buf + 2 || *end != '-' || !std::isfinite(sec)) {
    fail(err, errLen, "INDEX entry '%.60s': bad seconds field", buf);
    return false;
  }
  if (!(sec >= 0.0 && sec <= kMaxIndexSeconds)) {
    fail(err, errLen, "INDEX entry '%.60s': seconds %g outside 0..%.0f", buf, sec,
         kMaxIndexSeconds);
    return false;
  }
  const char* ts = end + 1;
  if (*ts < '0' || *ts > '9') {
    fail(err, errLen, "INDEX entry '%.60s': bad timestamp field", buf);
    return false;
  }
  char* tsEnd = nullptr;
  const unsigned long long t = std::strtoull(ts, &tsEnd, 10);
  if (*tsEnd != '.' || t > 0xFFFFFFFFull) {
    fail(err, errLen, "INDEX entry '%.60s': bad timestamp field", buf);
    return false;
  }
  const char* ext = tsEnd + 1;
  const char* want = buf[0] == 'r' ? "ppm" : (buf[0] == 'd' ? "pgm" : "dump");
  if (std::strcmp(ext, want) != 0) {
    fail(err, errLen, "INDEX entry '%.60s': expected extension .%s", buf, want);
    return false;
  }
  out->kind = buf[0];
  out->seconds = sec;
  out->timestamp = static_cast<uint32_t>(t);
  return true;
}

bool parseBobotLine(const char* line, size_t len, int* idx, float box[4], char* err,
                    size_t errLen) {
  char buf[256];
  if (!copyLine(line, len, buf, sizeof buf, err, errLen)) return false;
  const char* p = buf;
  while (isSpace(*p)) ++p;
  char* end = nullptr;
  const long i = std::strtol(p, &end, 10);
  if (end == p || i < 0 || i > 10000000 || !isSpace(*end)) {
    fail(err, errLen, "expected 'idx x y w h', no frame index");
    return false;
  }
  if (!parseFloats(end, box, 4, false, err, errLen)) return false;
  for (int k = 0; k < 4; ++k)
    if (box[k] < -1.f || box[k] > 2.f) {
      fail(err, errLen, "value %g is not normalised (expected 0..1)", static_cast<double>(box[k]));
      return false;
    }
  if (box[2] < 0.f || box[3] < 0.f) {
    fail(err, errLen, "negative width or height");
    return false;
  }
  *idx = static_cast<int>(i);
  return true;
}

bool parseOtbLine(const char* line, size_t len, float box[4], char* err, size_t errLen) {
  char buf[256];
  if (!copyLine(line, len, buf, sizeof buf, err, errLen)) return false;
  if (!parseFloats(buf, box, 4, true, err, errLen)) return false;
  if (box[2] < 0.f || box[3] < 0.f) {
    fail(err, errLen, "negative width or height");
    return false;
  }
  return true;
}

bool parseIntrinsics(const char* text, size_t len, CameraIntrinsics* out, char* err,
                     size_t errLen) {
  size_t pos = 0;
  const char* line = nullptr;
  size_t lineLen = 0;
  while (nextLine(text, len, &pos, &line, &lineLen)) {
    if (blankLine(line, lineLen) || line[0] == '#') continue;
    char buf[256];
    if (!copyLine(line, lineLen, buf, sizeof buf, err, errLen)) return false;
    float v[4];
    if (!parseFloats(buf, v, 4, true, err, errLen)) return false;
    for (int k = 0; k < 2; ++k)
      if (!(v[k] >= kMinFocalPx && v[k] <= kMaxFocalPx)) {
        fail(err, errLen, "%s %g outside %g..%g px", k == 0 ? "fx" : "fy",
             static_cast<double>(v[k]), static_cast<double>(kMinFocalPx),
             static_cast<double>(kMaxFocalPx));
        return false;
      }
    if (!(v[2] >= 0.f && v[2] <= static_cast<float>(kMaxImageWidth)) ||
        !(v[3] >= 0.f && v[3] <= static_cast<float>(kMaxImageHeight))) {
      fail(err, errLen, "principal point %g,%g outside 0,0..%d,%d px", static_cast<double>(v[2]),
           static_cast<double>(v[3]), kMaxImageWidth, kMaxImageHeight);
      return false;
    }
    *out = {v[0], v[1], v[2], v[3]};
    return true;
  }
  fail(err, errLen, "no 'fx fy cx cy' line");
  return false;
}

bool nextLine(const char* text, size_t len, size_t* pos, const char** line, size_t* lineLen) {
  if (*pos >= len) return false;
  const size_t start = *pos;
  size_t p = start;
  while (p < len && text[p] != '\n') ++p;
  size_t n = p - start;
  if (n > 0 && text[start + n - 1] == '\r') --n;
  *line = text + start;
  *lineLen = n;
  *pos = p < len ? p + 1 : p;
  return true;
}

bool blankLine(const char* line, size_t len) {
  for (size_t i = 0; i < len; ++i)
    if (!isSpace(line[i])) return false;
  return true;
}

bool parseFrameCount(const char* text, int* out) {
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || v < 1 || v > kMaxSpecFrames) return false;
  *out = static_cast<int>(v);
  return true;
}

}  // namespace cuetrack::rec
