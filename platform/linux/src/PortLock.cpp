#include "cuetrack/platform/linux/PortLock.hpp"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdio>
#include <cstdlib>
#include <cstring>

namespace cuetrack::platform {
namespace {

// The PID in a lock file (ASCII, HDB style, or anything strtol reads), 0 if none.
long readPid(const char* lockPath) {
  const int fd = ::open(lockPath, O_RDONLY | O_CLOEXEC | O_NOFOLLOW);
  if (fd < 0) return 0;
  char buf[32] = "";
  const ssize_t n = ::read(fd, buf, sizeof buf - 1);
  ::close(fd);
  if (n <= 0) return 0;
  buf[n] = '\0';
  const long pid = std::strtol(buf, nullptr, 10);
  return pid > 0 ? pid : 0;
}

bool alive(long pid) {
  return pid > 0 && (::kill(static_cast<pid_t>(pid), 0) == 0 || errno == EPERM);
}

}  // namespace

PortLock::PortLock(const char* lockDir) {
  std::snprintf(_dir, sizeof _dir, "%s", lockDir ? lockDir : kDefaultLockDir);
}

PortLock::~PortLock() {
  release();
}

bool PortLock::lockPathFor(const char* lockDir, const char* devicePath, char* out, size_t outLen) {
  char real[PATH_MAX];
  const char* dev = ::realpath(devicePath, real) ? real : devicePath;
  if (std::strncmp(dev, "/dev/", 5) == 0) dev += 5;
  while (*dev == '/') ++dev;
  const int n = std::snprintf(out, outLen, "%s/LCK..%s", lockDir, dev);
  if (n < 0 || static_cast<size_t>(n) >= outLen) return false;
  for (char* p = out + std::strlen(lockDir) + 6; *p; ++p)
    if (*p == '/') *p = '_';
  return true;
}

long PortLock::holder(const char* devicePath) const {
  char path[sizeof _lockPath];
  if (!lockPathFor(_dir, devicePath, path, sizeof path)) return 0;
  const long pid = readPid(path);
  return pid != static_cast<long>(::getpid()) && alive(pid) ? pid : 0;
}

bool PortLock::acquire(const char* devicePath, char* err, size_t errLen) {
  release();
  if (!lockPathFor(_dir, devicePath, _lockPath, sizeof _lockPath)) {
    _lockPath[0] = '\0';
    return true;  // no lock file for a name this long; the device's own locks remain
  }
  for (int attempt = 0; attempt < 2; ++attempt) {
    const int fd = ::open(_lockPath, O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
    if (fd >= 0) {
      char pid[16];
      const int n = std::snprintf(pid, sizeof pid, "%10ld\n", static_cast<long>(::getpid()));
      const bool ok = ::write(fd, pid, static_cast<size_t>(n)) == n;
      ::close(fd);
      if (!ok) {  // a lock file without a PID would look stale to the next one
        ::unlink(_lockPath);
        return true;
      }
      _held = true;
      return true;
    }
    if (errno != EEXIST) return true;  // cannot write the lock folder: not ours to manage
    const long pid = readPid(_lockPath);
    if (pid == static_cast<long>(::getpid())) {  // ours, left by an earlier open
      _held = true;
      return true;
    }
    if (alive(pid)) {
      std::snprintf(err, errLen, "%s: in use by process %ld (lock file %s)", devicePath, pid,
                    _lockPath);
      return false;
    }
    ::unlink(_lockPath);  // stale: its process is gone
  }
  return true;
}

void PortLock::release() {
  if (_held) ::unlink(_lockPath);
  _held = false;
}

}  // namespace cuetrack::platform
