#include "cuetrack/platform/HostPort.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

namespace cuetrack::platform {

bool splitHostPort(const char* text, char* host, size_t hostCap, unsigned* port) {
  const char* colon = nullptr;
  const char* h = text;
  size_t hostLen = 0;
  if (text[0] == '[') {  // [v6]:port
    const char* close = std::strchr(text, ']');
    if (close == nullptr || close[1] != ':') return false;
    h = text + 1;
    hostLen = static_cast<size_t>(close - h);
    colon = close + 1;
  } else {
    colon = std::strrchr(text, ':');
    if (colon == nullptr || std::strchr(text, ':') != colon) return false;
    hostLen = static_cast<size_t>(colon - text);
  }
  if (hostLen == 0 || hostLen + 1 > hostCap) return false;
  char* end = nullptr;
  errno = 0;
  const unsigned long p = std::strtoul(colon + 1, &end, 10);
  if (colon[1] < '0' || colon[1] > '9' || *end != '\0' || errno != 0 || p < 1 || p > 65535)
    return false;
  std::memcpy(host, h, hostLen);
  host[hostLen] = '\0';
  *port = static_cast<unsigned>(p);
  return true;
}

}  // namespace cuetrack::platform
