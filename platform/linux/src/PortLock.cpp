#include "cuetrack/platform/linux/PortLock.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <climits>
#include <cstdint>
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

enum class Holds : uint8_t { Yes, No, Unknown };

// Whether process pid has the device open: its open files (/proc/PID/fd) against the
// device's number. Unknown where we may not look (another user's process, we not root).
Holds holdsDevice(long pid, const char* devicePath) {
  struct stat dev {};
  if (::stat(devicePath, &dev) != 0 || !S_ISCHR(dev.st_mode)) return Holds::Unknown;
  char dir[48];
  std::snprintf(dir, sizeof dir, "/proc/%ld/fd", pid);
  DIR* d = ::opendir(dir);
  if (d == nullptr) return Holds::Unknown;
  Holds holds = Holds::No;
  while (const dirent* e = ::readdir(d)) {
    struct stat st {};
    if (e->d_name[0] != '.' && ::fstatat(::dirfd(d), e->d_name, &st, 0) == 0 &&
        S_ISCHR(st.st_mode) && st.st_rdev == dev.st_rdev) {
      holds = Holds::Yes;
      break;
    }
  }
  ::closedir(d);
  return holds;
}

// A lock file is honoured only while its process holds the device: /run/lock is writable
// by every local user, and a planted file naming a live process (PID 1) would keep us off
// the port for good. Where we may not look at the process's files, the lock file must at
// least belong to the process's user. False with the reason in why.
bool honoured(long pid, const char* devicePath, const char* lockPath, char* why, size_t n) {
  if (!alive(pid)) {
    std::snprintf(why, n, "process %ld is gone", pid);
    return false;
  }
  switch (holdsDevice(pid, devicePath)) {
    case Holds::Yes:
      return true;
    case Holds::No:
      std::snprintf(why, n, "process %ld does not have %s open", pid, devicePath);
      return false;
    case Holds::Unknown:
      break;
  }
  char proc[32];
  std::snprintf(proc, sizeof proc, "/proc/%ld", pid);
  struct stat owner {
  }, lock{};
  if (::stat(proc, &owner) != 0 || ::lstat(lockPath, &lock) != 0) return true;  // cannot tell
  if (owner.st_uid == lock.st_uid) return true;
  std::snprintf(why, n, "process %ld runs as user %u, the lock file belongs to user %u", pid,
                static_cast<unsigned>(owner.st_uid), static_cast<unsigned>(lock.st_uid));
  return false;
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
  char why[160];
  return pid != static_cast<long>(::getpid()) && honoured(pid, devicePath, path, why, sizeof why)
             ? pid
             : 0;
}

bool PortLock::acquire(const char* devicePath, char* err, size_t errLen) {
  release();
  _note[0] = '\0';
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
    struct stat st {};
    if (::lstat(_lockPath, &st) == 0 && !S_ISREG(st.st_mode)) {
      // A folder (or a link) by the lock's name: no process holds it, and it is not ours to
      // remove. The port is used, but nothing locks it against another program.
      std::snprintf(_note, sizeof _note,
                    "%s: %s is not a lock file (a folder or a link): the port is used without "
                    "a lock; remove it so the next run can lock the port",
                    devicePath, _lockPath);
      return true;
    }
    const long pid = readPid(_lockPath);
    if (pid == static_cast<long>(::getpid())) {  // ours, left by an earlier open
      _held = true;
      return true;
    }
    char why[160] = "no process named in it";
    if (pid > 0 && honoured(pid, devicePath, _lockPath, why, sizeof why)) {
      std::snprintf(err, errLen, "%s: in use by process %ld (lock file %s)", devicePath, pid,
                    _lockPath);
      return false;
    }
    if (::unlink(_lockPath) != 0) {  // stale, but not ours to remove
      std::snprintf(_note, sizeof _note,
                    "%s: cannot remove the stale lock file %s (%s; %s): the port is used "
                    "without a lock",
                    devicePath, _lockPath, why, std::strerror(errno));
      return true;
    }
    std::snprintf(_note, sizeof _note, "%s: replaced the stale lock file %s (%s)", devicePath,
                  _lockPath, why);
  }
  return true;
}

void PortLock::release() {
  if (_held) ::unlink(_lockPath);
  _held = false;
}

}  // namespace cuetrack::platform
