#include "cuetrack/platform/linux/FdTrackSink.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "cuetrack/platform/TrackText.hpp"

namespace cuetrack::platform {

FdTrackSink::~FdTrackSink() {
  if (_ownsFd && _fd >= 0) ::close(_fd);
}

bool FdTrackSink::openFile(const char* path, TextFormat format) {
  _format = format;
  if (std::strcmp(path, "-") == 0) {
    attachStdout(format);
  } else {
    std::snprintf(_name, sizeof _name, "%s", path);
    // O_NONBLOCK: a FIFO with no reader must not block open() forever (ENXIO instead);
    // the writes themselves block as usual.
    _fd = ::open(path, O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC | O_NONBLOCK, 0644);
    if (_fd < 0) {
      std::snprintf(_error, sizeof _error, "%s: cannot create: %s", path,
                    errno == ENXIO ? "a FIFO with no reader" : std::strerror(errno));
      return false;
    }
    const int flags = ::fcntl(_fd, F_GETFL);
    if (flags >= 0) ::fcntl(_fd, F_SETFL, flags & ~O_NONBLOCK);
    _ownsFd = true;
    _wholeBytes = 0;
  }
  if (format == TextFormat::Csv) {
    const char* h = trackCsvHeader();
    return writeAll(h, std::strlen(h));
  }
  return true;
}

bool FdTrackSink::close() {
  if (!_ownsFd || _fd < 0) return true;
  const bool synced = ::fsync(_fd) == 0 || errno == EINVAL || errno == EROFS;  // not a file
  const int syncErr = errno;
  const bool closed = ::close(_fd) == 0;
  const int closeErr = errno;
  _fd = -1;
  _ownsFd = false;
  if (synced && closed) return true;
  std::snprintf(_error, sizeof _error, "%s: write failed at close: %s", _name,
                std::strerror(synced ? closeErr : syncErr));
  return false;
}

void FdTrackSink::attachStdout(TextFormat format) {
  _format = format;
  _fd = 1;
  _ownsFd = false;
  _wholeBytes = -1;  // a pipe or terminal cannot be cut back
  std::snprintf(_name, sizeof _name, "stdout");
}

bool FdTrackSink::write(const ctp_track_t& track) {
  char line[256];
  const size_t n = _format == TextFormat::Csv ? formatTrackCsvRow(track, line, sizeof line)
                                              : formatTrackLine(track, line, sizeof line);
  return writeAll(line, n);
}

bool FdTrackSink::writeAll(const char* data, size_t len) {
  if (_fd < 0) {
    std::snprintf(_error, sizeof _error, "%s: not open", _name);
    return false;
  }
  const size_t whole = len;
  size_t done = 0;
  while (done < len) {
    const ssize_t w = ::write(_fd, data + done, len - done);
    if (w < 0) {
      if (errno == EINTR) continue;
      const int err = errno;
      // A full disk takes part of a row and refuses the rest: cut the file back to its
      // last whole row, so a reader never takes half a row for a short one.
      const bool cut = done > 0 && _wholeBytes >= 0 && ::ftruncate(_fd, _wholeBytes) == 0 &&
                       ::lseek(_fd, _wholeBytes, SEEK_SET) == _wholeBytes;
      std::snprintf(_error, sizeof _error, "%s: write failed: %s%s", _name, std::strerror(err),
                    cut ? " (the partial row was removed)" : "");
      return false;
    }
    done += static_cast<size_t>(w);
  }
  if (_wholeBytes >= 0) _wholeBytes += static_cast<off_t>(whole);
  return true;
}

}  // namespace cuetrack::platform
