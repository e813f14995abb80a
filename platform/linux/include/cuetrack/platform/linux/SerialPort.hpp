// A serial device through termios: 8N1, raw, no flow control, non-blocking.
// Reads wait with poll(); writes never wait (a full buffer gives WouldBlock).
// A vanished device (USB unplugged, pty peer gone) gives Closed; reopen()
// opens the same path again when it is back. The port is ours alone while open: a UUCP
// lock file (PortLock), flock() and TIOCEXCL; a second opener is refused with a line
// naming the holder's PID when known.
#pragma once

#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/linux/PortLock.hpp"

namespace cuetrack::platform {

class SerialPort final : public ByteStream {
 public:
  SerialPort() = default;
  explicit SerialPort(const char* lockDir) : _lock(lockDir) {}
  ~SerialPort() override;
  SerialPort(const SerialPort&) = delete;
  SerialPort& operator=(const SerialPort&) = delete;

  static bool baudSupported(int baud);  // 9600 ... 921600
  // Remembers path and baud for reopen(). False with error() set on failure.
  bool open(const char* path, int baud);

  IoResult read(uint8_t* buf, size_t cap, int timeoutMs) override;
  IoResult write(const uint8_t* data, size_t len) override;
  bool waitWritable(int timeoutMs) override;
  bool isOpen() const override { return _fd >= 0; }
  bool reopen() override;
  void close() override;  // also gives up the lock
  const char* error() const override { return _error; }
  const char* name() const override { return _path; }
  // After open(): one line when a stale lock file was replaced (PortLock::note()), else "".
  const char* notice() const { return _lock.note(); }

 private:
  bool openFd();
  void closeFd();
  void inUse(const char* how);
  IoResult fail(const char* what, int err);

  PortLock _lock;
  int _fd{-1};
  int _baud{115200};
  char _path[256]{};
  char _error[384]{};
};

}  // namespace cuetrack::platform
