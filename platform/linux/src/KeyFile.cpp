#include "cuetrack/platform/linux/KeyFile.hpp"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <ctime>

namespace cuetrack::platform {

bool readKeyFile(const char* path, uint8_t* out, size_t size, char* err, size_t errLen) {
  // O_NONBLOCK: a FIFO or a device opens at once rather than waiting for a writer, and
  // is then refused as not a regular file (a service pointed at one must say so, not hang).
  const int fd = ::open(path, O_RDONLY | O_CLOEXEC | O_NONBLOCK | O_NOCTTY);
  if (fd < 0) {
    std::snprintf(err, errLen, "%s: cannot read the key: %s", path, std::strerror(errno));
    return false;
  }
  struct stat st {};
  bool ok = false;
  if (::fstat(fd, &st) != 0 || !S_ISREG(st.st_mode)) {
    std::snprintf(err, errLen, "%s: not a regular file", path);
  } else if ((st.st_mode & (S_IRWXG | S_IRWXO)) != 0) {
    std::snprintf(err, errLen, "%s: the key is open to group or others (mode %03o); chmod 600 %s",
                  path, static_cast<unsigned>(st.st_mode & 0777), path);
  } else if (st.st_size != static_cast<off_t>(size)) {
    std::snprintf(err, errLen, "%s: a key is exactly %zu bytes, this file has %lld", path, size,
                  static_cast<long long>(st.st_size));
  } else {
    ok = ::read(fd, out, size) == static_cast<ssize_t>(size);
    if (!ok) std::snprintf(err, errLen, "%s: cannot read the key: %s", path, std::strerror(errno));
  }
  if (ok && size > 0) {  // all zero, or one byte over and over: no secret at all
    size_t same = 1;
    while (same < size && out[same] == out[0]) ++same;
    if (same == size) {
      std::snprintf(err, errLen,
                    "%s: the key is one byte (0x%02x) repeated: not a secret; make one with "
                    "head -c %zu /dev/urandom",
                    path, out[0], size);
      ok = false;
    }
  }
  if (!ok) std::memset(out, 0, size);
  ::close(fd);
  return ok;
}

uint64_t signingTimestampNow() {
  timespec ts{};
  constexpr time_t kEpoch2015 = 1420070400;
  if (::clock_gettime(CLOCK_REALTIME, &ts) != 0 || ts.tv_sec < kEpoch2015) return 0;
  return static_cast<uint64_t>(ts.tv_sec - kEpoch2015) * 100000u +
         static_cast<uint64_t>(ts.tv_nsec) / 10000u;
}

}  // namespace cuetrack::platform
