// Track messages as text to a file descriptor: human lines (stdout) or CSV with a
// header (--out FILE). One write(2) per message, so a full disk or a closed pipe
// is seen at once and reported as one line naming the file. A file holds whole rows
// only: a row the disk took only part of is cut off again.
#pragma once

#include <sys/types.h>

#include "cuetrack/platform/TrackSink.hpp"

namespace cuetrack::platform {

enum class TextFormat : uint8_t { Line, Csv };

class FdTrackSink final : public TrackSink {
 public:
  FdTrackSink() = default;
  ~FdTrackSink() override;
  FdTrackSink(const FdTrackSink&) = delete;
  FdTrackSink& operator=(const FdTrackSink&) = delete;

  // Creates/truncates path ("-" = stdout). CSV writes its header here.
  bool openFile(const char* path, TextFormat format);
  void attachStdout(TextFormat format);
  // At the end of a run: a file is synced and closed (some file systems report a full
  // disk only then). False with error() set when that fails; stdout is left open.
  bool close();

  bool write(const ctp_track_t& track) override;
  const char* error() const override { return _error; }
  const char* name() const override { return _name; }

 private:
  bool writeAll(const char* data, size_t len);

  int _fd{-1};
  bool _ownsFd{false};
  off_t _wholeBytes{-1};  // file size up to the last whole row; -1: stdout, not cut back
  TextFormat _format{TextFormat::Line};
  char _name[256]{};
  char _error[384]{};
};

}  // namespace cuetrack::platform
