#include "cuetrack/cli/Values.hpp"

#include <sys/stat.h>

#include <cerrno>
#include <climits>
#include <cmath>
#include <cstdlib>
#include <cstring>

#include "cuetrack/platform/DecimalText.hpp"
#include "cuetrack/platform/HostPort.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"

namespace cuetrack::cli {

std::string wholeNumber(const std::string& text, long lo, long hi, long* out) {
  const std::string want =
      "expected a whole number in " + std::to_string(lo) + ".." + std::to_string(hi);
  const char* s = text.c_str();
  // A plain decimal without a fraction; no sign but '-' ("+1" is refused).
  if (s[0] == '+' || !platform::plainDecimal(s, false)) return want;
  char* end = nullptr;
  errno = 0;
  const long v = std::strtol(s, &end, 10);
  if (*end != '\0' || errno != 0 || v < lo || v > hi) return want;
  *out = v;
  return "";
}

std::string decimal(const std::string& text, double lo, double hi, double* out) {
  // strtod alone would also read blanks, hex ("0x10"), exponents ("1e3"), inf and nan.
  const bool plain = platform::plainDecimal(text.c_str(), true);
  char* end = nullptr;
  errno = 0;
  const double v = plain ? std::strtod(text.c_str(), &end) : 0.0;
  if (!plain || errno != 0 || *end != '\0' || !(v >= lo && v <= hi))
    return "expected a number in " + std::to_string(lo) + ".." + std::to_string(hi);
  *out = v;
  return "";
}

std::string seed(const std::string& text, uint64_t* out) {
  const char* s = text.c_str();
  char* end = nullptr;
  errno = 0;
  const unsigned long long v = std::strtoull(s, &end, 10);
  // strtoull takes "-1" as 2^64-1: only plain digits are a seed.
  if (*s < '0' || *s > '9' || *end != '\0' || errno != 0)
    return "expected a non-negative whole number";
  *out = v;
  return "";
}

std::string imageSize(const std::string& text, int minSide, int maxW, int maxH, int* w, int* h) {
  const size_t x = text.find('x');
  long a = 0, b = 0;
  if (x == std::string::npos) return "expected WxH";
  if (!wholeNumber(text.substr(0, x), minSide, maxW, &a).empty() ||
      !wholeNumber(text.substr(x + 1), minSide, maxH, &b).empty())
    return "expected WxH within " + std::to_string(minSide) + "x" + std::to_string(minSide) + ".." +
           std::to_string(maxW) + "x" + std::to_string(maxH);
  *w = static_cast<int>(a);
  *h = static_cast<int>(b);
  return "";
}

std::string numbers(const std::string& text, int n, float limit, float* out) {
  const char* s = text.c_str();
  const std::string want = "expected " + std::to_string(n) + " numbers A,B,... each within +-" +
                           std::to_string(static_cast<long>(limit));
  for (int i = 0; i < n; ++i) {
    // A plain decimal up to the next ',' (strtof would also read "0x123", "1e2", " 1").
    if (!platform::plainDecimal(s, true, ',')) return want;
    char* end = nullptr;
    out[i] = std::strtof(s, &end);
    // inf, nan and absurd values would reach the tracker as something it "tracks".
    if (end == s || !std::isfinite(out[i]) || std::fabs(out[i]) > limit) return want;
    s = end;
    if (i < n - 1) {
      if (*s != ',') return want;
      ++s;
    }
  }
  return *s == '\0' ? "" : want;
}

std::string box(const std::string& text, Box* out) {
  float v[4];
  if (!numbers(text, 4, 100000.f, v).empty() || !(v[2] > 0.f) || !(v[3] > 0.f))
    return "expected X,Y,W,H [px], finite, W,H > 0, none beyond 100000";
  *out = Box{v[0], v[1], v[2], v[3]};
  return "";
}

std::string baudRate(const std::string& text, int* out) {
  long b = 0;
  if (!wholeNumber(text, LONG_MIN, LONG_MAX, &b).empty()) return "not a number";
  if (b < 1 || b > 4000000 || !platform::SerialPort::baudSupported(static_cast<int>(b)))
    return "unsupported (9600..921600)";
  *out = static_cast<int>(b);
  return "";
}

std::string hostPort(const std::string& text) {
  char host[256];
  unsigned port = 0;
  if (!platform::splitHostPort(text.c_str(), host, sizeof host, &port))
    return "expected HOST:PORT, port 1..65535";
  return "";
}

std::string existingFile(const std::string& text) {
  struct stat st {};
  if (::stat(text.c_str(), &st) != 0) return std::strerror(errno);
  if (S_ISDIR(st.st_mode)) return "is a folder, expected a file";
  return "";
}

std::string oneOf(const std::string& text, const char* choices, int* out) {
  int index = 0;
  for (const char* c = choices;; ++index) {
    const char* bar = std::strchr(c, '|');
    const size_t n = bar ? static_cast<size_t>(bar - c) : std::strlen(c);
    if (text.size() == n && text.compare(0, n, c, n) == 0) {
      *out = index;
      return "";
    }
    if (!bar) break;
    c = bar + 1;
  }
  std::string list = choices;
  for (char& ch : list)
    if (ch == '|') ch = ',';
  return "expected one of " + list;
}

}  // namespace cuetrack::cli
