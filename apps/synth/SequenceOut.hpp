// Writing a sequence in one of the recorded formats, shared by cuetrack-synth and
// cuetrack-convert. Formats: "fakenect" (everywhere); with OpenCV also "rgbd" (RGB-D
// folder), "otb" (OTB folder, JPEG, colour only) and "avi" (BoBoT-style MJPG video +
// .gt.txt; `dir` is then the .avi path).
#pragma once

#include <cstddef>
#include <memory>
#include <string>

#include "cuetrack/cli/OutputGuard.hpp"
#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack {

class SequenceOut {
 public:
  virtual ~SequenceOut() = default;
  virtual bool write(const FrameSlot& frame) = 0;
  virtual bool close() = 0;
  virtual const char* error() const = 0;
  // After a failure: removes what this output created (the folder it made, or the
  // partial .avi and .gt.txt in their staging folder), so a later run cannot read a
  // partial output as a whole one. A file the run did not create is never removed.
  void discard();
  // After a successful close: the staged files moved to their names (replacing, with
  // --force, the earlier ones only now). False with a line in err.
  bool commit(char* err, size_t errLen);

  // Set by openSequenceOut.
  std::string removeDir;  // a folder it made: removed whole
  struct Move {
    std::string from, to;
  };
  Move moves[2];  // an .avi and its .gt.txt, staged in removeDir
};

// nullptr with a line in err for an unknown format or an output that cannot be created.
// fps: the source's frame rate (FrameSource::nominalFps), the avi container's rate; 0 =
// unknown, then 30 (the Kinect's). An existing .avi or its .gt.txt is refused unless
// `force` (folder formats refuse a folder holding a recording, always). An .avi and its
// .gt.txt are written in a staging folder beside them and take their names on commit().
std::unique_ptr<SequenceOut> openSequenceOut(const char* format, const char* dir, const char* name,
                                             double fps, char* err, size_t errLen,
                                             bool force = false);

// Copies every frame of src into out; returns frames written, -1 on error (line in err).
// On an error, or when stopRequested() turns true (a signal), the partial output is
// discarded and err says so.
int copySequence(FrameSource& src, SequenceOut& out, FrameSlot& slot, char* err, size_t errLen,
                 bool (*stopRequested)() = nullptr);

// The write step of cuetrack-synth and cuetrack-convert: opens `format` at `out`
// (openSequenceOut, `name` the sequence's name), copies every frame of src into it through
// slot, a SIGINT/SIGTERM/SIGHUP removing the partial output (copySequence), and reports a
// failure as one line "TOOL: ERROR" on stderr. Returns the exit code: 0 with the frames
// written in *frames, 2 for an unknown format (a bad command line), 1 for any other failure.
int writeSequence(const char* tool, FrameSource& src, const char* format, const char* out,
                  const char* name, bool force, FrameSlot& slot, int* frames);

// Before the source is opened: `out` in `format` (an .avi and its .gt.txt, or a folder)
// may not be, or lie inside, an input of `inputs` (the one guard of every tool,
// cli::OutputGuard), --force or not. 0, or 2 after the line "TOOL: ..." on stderr.
int checkSequenceOut(const char* tool, const char* format, const char* out,
                     const cli::OutputGuard& inputs);

}  // namespace cuetrack
