// A serial device used by one program at a time. Two readers of one port each get part
// of the stream and neither knows; ModemManager probing a new USB serial device does the
// same. So a port is claimed the conventional way, as minicom, picocom and pppd do: a
// UUCP lock file (lockDir/LCK..ttyUSB0, the owner's PID as ten characters and a newline).
// SerialPort adds flock() and TIOCEXCL on the device itself, which cover programs that
// ignore lock files (but not root, for TIOCEXCL).
#pragma once

#include <cstddef>

namespace cuetrack::platform {

inline constexpr const char* kDefaultLockDir = "/run/lock";

class PortLock {
 public:
  explicit PortLock(const char* lockDir = kDefaultLockDir);
  ~PortLock();
  PortLock(const PortLock&) = delete;
  PortLock& operator=(const PortLock&) = delete;

  // Takes the lock file of devicePath (symlinks resolved: two names of one device share
  // it). False, with one line in err naming the device and the holder's PID, when the
  // process it names holds the device (alive, with the device open; where its open files
  // cannot be seen, running as the lock file's owner). Any other lock file is stale and
  // replaced, with one line in note() saying why. A lock folder we cannot write (missing,
  // read-only, no permission) is not an error: held() stays false and the device's own
  // locks must do.
  bool acquire(const char* devicePath, char* err, size_t errLen);
  // After acquire(): "DEV: replaced the stale lock file ... (why)", or "" when none was.
  const char* note() const { return _note; }
  void release();  // removes the lock file if we made it
  bool held() const { return _held; }
  const char* path() const { return _lockPath; }

  // The PID in devicePath's lock file if a process other than us holds the device by the
  // rule of acquire(), else 0.
  long holder(const char* devicePath) const;

  // lockDir/LCK..NAME for a device: NAME is the path below /dev with '/' as '_'
  // (/dev/ttyUSB0 -> LCK..ttyUSB0, /dev/pts/3 -> LCK..pts_3). False if too long.
  static bool lockPathFor(const char* lockDir, const char* devicePath, char* out, size_t outLen);

 private:
  char _dir[128]{};
  char _lockPath[384]{};
  char _note[768]{};
  bool _held{false};
};

}  // namespace cuetrack::platform
