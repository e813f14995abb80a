#include "cuetrack/platform/linux/SerialPort.hpp"

#include <fcntl.h>
#include <poll.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <termios.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace cuetrack::platform {
namespace {

struct BaudEntry {
  int baud;
  speed_t speed;
};
constexpr BaudEntry kBauds[] = {
    {9600, B9600},     {19200, B19200},   {38400, B38400},   {57600, B57600},   {115200, B115200},
    {230400, B230400}, {460800, B460800}, {500000, B500000}, {576000, B576000}, {921600, B921600},
};

bool speedOf(int baud, speed_t* out) {
  for (const BaudEntry& e : kBauds) {
    if (e.baud == baud) {
      *out = e.speed;
      return true;
    }
  }
  return false;
}

// errno values meaning the device or its peer is gone (unplugged USB, closed pty).
bool isGone(int err) {
  return err == EIO || err == ENXIO || err == ENODEV || err == EPIPE || err == EBADF;
}

}  // namespace

SerialPort::~SerialPort() {
  close();
}

bool SerialPort::baudSupported(int baud) {
  speed_t s;
  return speedOf(baud, &s);
}

bool SerialPort::open(const char* path, int baud) {
  close();
  std::snprintf(_path, sizeof _path, "%s", path);
  _baud = baud;
  speed_t s;
  if (!speedOf(baud, &s)) {
    std::snprintf(_error, sizeof _error, "%s: unsupported baud rate %d (9600..921600)", _path,
                  baud);
    return false;
  }
  // The lock file first: it names the holder, which the device's own locks cannot.
  if (!_lock.acquire(_path, _error, sizeof _error)) return false;
  if (!openFd()) {
    _lock.release();
    return false;
  }
  return true;
}

bool SerialPort::reopen() {
  if (_fd >= 0) return true;
  // close() gave up the lock file with the device: take it again first (the holder of a
  // device that came back to someone else is named, and we stay out).
  const bool takeLock = !_lock.held();
  if (takeLock && !_lock.acquire(_path, _error, sizeof _error)) return false;
  if (!openFd()) {
    if (takeLock) _lock.release();  // a lock kept through an outage stays ours
    return false;
  }
  return true;
}

bool SerialPort::openFd() {
  const int fd = ::open(_path, O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0 && errno == EBUSY) {  // another program set TIOCEXCL
    inUse("opened exclusively");
    return false;
  }
  if (fd < 0) {
    std::snprintf(_error, sizeof _error, "%s: cannot open: %s", _path, std::strerror(errno));
    return false;
  }
  termios tio{};
  speed_t speed = B115200;
  speedOf(_baud, &speed);
  if (tcgetattr(fd, &tio) != 0) {
    std::snprintf(_error, sizeof _error, "%s: not a serial port: %s", _path, std::strerror(errno));
    ::close(fd);
    return false;
  }
  // One program per port: flock covers programs that skip lock files; TIOCEXCL makes
  // further open()s fail with EBUSY (except for root).
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0 && errno == EWOULDBLOCK) {
    ::close(fd);
    inUse("locked");
    return false;
  }
  ::ioctl(fd, TIOCEXCL);
  cfmakeraw(&tio);  // no echo, no line editing, no CR/LF translation, 8 bits
  tio.c_cflag &= ~static_cast<tcflag_t>(PARENB | CSTOPB | CSIZE | CRTSCTS);
  tio.c_cflag |= CS8 | CLOCAL | CREAD;
  tio.c_iflag &= ~static_cast<tcflag_t>(IXON | IXOFF | IXANY);
  tio.c_cc[VMIN] = 0;
  tio.c_cc[VTIME] = 0;
  cfsetispeed(&tio, speed);
  cfsetospeed(&tio, speed);
  if (tcsetattr(fd, TCSANOW, &tio) != 0) {
    std::snprintf(_error, sizeof _error, "%s: cannot configure %d 8N1 raw: %s", _path, _baud,
                  std::strerror(errno));
    ::close(fd);
    return false;
  }
  tcflush(fd, TCIFLUSH);  // stale bytes from before we opened are not ours
  _fd = fd;
  _error[0] = '\0';
  return true;
}

void SerialPort::closeFd() {
  if (_fd >= 0) ::close(_fd);
  _fd = -1;
}

void SerialPort::close() {
  closeFd();
  _lock.release();
}

void SerialPort::inUse(const char* how) {
  const long pid = _lock.holder(_path);
  if (pid > 0)
    std::snprintf(_error, sizeof _error, "%s: in use by process %ld (%s)", _path, pid, how);
  else
    std::snprintf(_error, sizeof _error, "%s: in use by another program (%s; holder unknown)",
                  _path, how);
}

IoResult SerialPort::fail(const char* what, int err) {
  std::snprintf(_error, sizeof _error, "%s: %s: %s", _path, what, std::strerror(err));
  if (isGone(err)) {
    closeFd();  // the lock stays ours until the device is back (reopen) or close()
    return {IoStatus::Closed, 0};
  }
  return {IoStatus::Error, 0};
}

IoResult SerialPort::read(uint8_t* buf, size_t cap, int timeoutMs) {
  if (_fd < 0) return {IoStatus::Closed, 0};
  pollfd p{_fd, POLLIN, 0};
  const int r = ::poll(&p, 1, timeoutMs);
  if (r < 0) return errno == EINTR ? IoResult{IoStatus::Ok, 0} : fail("poll failed", errno);
  if (r == 0) return {IoStatus::Ok, 0};
  if (p.revents & POLLNVAL) return fail("poll failed", EBADF);
  const ssize_t n = ::read(_fd, buf, cap);
  if (n > 0) return {IoStatus::Ok, static_cast<size_t>(n)};
  if (n < 0 && (errno == EAGAIN || errno == EINTR)) return {IoStatus::Ok, 0};
  if (n < 0) return fail("read failed", errno);
  // 0 bytes although poll said readable: hang-up.
  if (p.revents & (POLLHUP | POLLERR)) return fail("read failed", EIO);
  return {IoStatus::Ok, 0};
}

bool SerialPort::waitWritable(int timeoutMs) {
  if (_fd < 0) return false;
  pollfd p{_fd, POLLOUT, 0};
  return ::poll(&p, 1, timeoutMs) > 0 && (p.revents & POLLOUT) != 0;
}

IoResult SerialPort::write(const uint8_t* data, size_t len) {
  if (_fd < 0) return {IoStatus::Closed, 0};
  for (;;) {
    const ssize_t n = ::write(_fd, data, len);
    if (n >= 0) return {IoStatus::Ok, static_cast<size_t>(n)};
    if (errno == EINTR) continue;
    if (errno == EAGAIN) return {IoStatus::WouldBlock, 0};
    return fail("write failed", errno);
  }
}

}  // namespace cuetrack::platform
