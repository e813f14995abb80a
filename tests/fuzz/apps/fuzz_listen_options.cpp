// cuetrack-listen's command line (NUL-separated argv): one of three results, an error is
// a line, and an accepted run has a port, a supported rate and parsed commands.
#include <cstddef>
#include <cstdint>
#include <cstring>

#include "ListenOptions.hpp"

using namespace cuetrack::listen;

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  static char text[4096];
  static ListenOptions o;
  if (size >= sizeof text) return 0;
  std::memcpy(text, data, size);
  text[size] = '\0';
  char* argv[65];
  int argc = 0;
  argv[argc++] = const_cast<char*>("cuetrack-listen");
  for (size_t start = 0; start <= size && argc < 64;) {
    argv[argc++] = text + start;
    start += std::strlen(text + start) + 1;
  }
  argv[argc] = nullptr;
  char err[512] = "";
  const ListenParse r = parseListenOptions(argc, argv, &o, err, sizeof err);
  if (r == ListenParse::Error &&
      (err[0] == '\0' || (std::strchr(err, '\n') && !std::memchr(data, '\n', size))))
    __builtin_trap();
  if (r == ListenParse::Run) {
    if (!o.portPath || o.baud < 9600 || o.baud > 921600) __builtin_trap();
    if (o.maxTracks == 0 || o.idleS == 0) __builtin_trap();
    if (o.numSends < 0 || o.numSends > ListenOptions::kMaxSends) __builtin_trap();
    for (int i = 0; i < o.numSends; ++i)
      if (o.commands[i].id != i + 1) __builtin_trap();
  }
  return 0;
}
