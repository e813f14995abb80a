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
  }
  if (format == TextFormat::Csv) {
    const char* h = trackCsvHeader();
    return writeAll(h, std::strlen(h));
  }
  return true;
}

void FdTrackSink::attachStdout(TextFormat format) {
  _format = format;
  _fd = 1;
  _ownsFd = false;
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
  while (len > 0) {
    const ssize_t w = ::write(_fd, data, len);
    if (w < 0) {
      if (errno == EINTR) continue;
      std::snprintf(_error, sizeof _error, "%s: write failed: %s", _name, std::strerror(errno));
      return false;
    }
    data += w;
    len -= static_cast<size_t>(w);
  }
  return true;
}

}  // namespace cuetrack::platform
