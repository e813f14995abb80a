#include "SequenceOut.hpp"

#include <ftw.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#if CUETRACK_HAVE_OPENCV
#include "cuetrack/drivers/OpenCvSources.hpp"
#endif

namespace cuetrack {

namespace {

int removeEntry(const char* path, const struct stat*, int, FTW*) {
  return ::remove(path);  // files, then (FTW_DEPTH) their emptied folders
}

}  // namespace

void SequenceOut::discard() {
  if (!removeDir.empty()) nftw(removeDir.c_str(), removeEntry, 16, FTW_DEPTH | FTW_PHYS);
  for (const std::string& f : removeFiles)
    if (!f.empty()) ::unlink(f.c_str());
}

namespace {
template <typename W>
class Out final : public SequenceOut {
 public:
  W writer;
  bool write(const FrameSlot& f) override { return writer.write(f); }
  bool close() override { return writer.close(); }
  const char* error() const override { return writer.error(); }
};
}  // namespace

namespace {
std::unique_ptr<SequenceOut> openOut(const char* format, const char* dir, const char* name,
                                     [[maybe_unused]] double fps, char* err, size_t errLen) {
  if (std::strcmp(format, "fakenect") == 0) {
    auto o = std::make_unique<Out<FakenectWriter>>();
    if (!o->writer.open(dir, name)) {
      std::snprintf(err, errLen, "%s", o->writer.error());
      return nullptr;
    }
    return o;
  }
  if (std::strcmp(format, "rgbd") == 0) {
#if CUETRACK_HAVE_OPENCV
    auto o = std::make_unique<Out<RgbdFolderWriter>>();
    if (!o->writer.open(dir, name)) {
      std::snprintf(err, errLen, "%s", o->writer.error());
      return nullptr;
    }
    return o;
#else
    std::snprintf(err, errLen, "%s: the rgbd format (PNG) needs a host build with OpenCV", dir);
    return nullptr;
#endif
  }
#if CUETRACK_HAVE_OPENCV
  if (std::strcmp(format, "otb") == 0) {
    auto o = std::make_unique<Out<OtbFolderWriter>>();
    if (!o->writer.open(dir)) {
      std::snprintf(err, errLen, "%s", o->writer.error());
      return nullptr;
    }
    return o;
  }
  if (std::strcmp(format, "avi") == 0) {
    auto o = std::make_unique<Out<BobotVideoWriter>>();
    if (!o->writer.open(dir, fps > 0.0 ? fps : 30.0)) {
      std::snprintf(err, errLen, "%s", o->writer.error());
      return nullptr;
    }
    return o;
  }
#endif
  std::snprintf(err, errLen, "unknown format '%s' (fakenect, rgbd; otb, avi with OpenCV)", format);
  return nullptr;
}
}  // namespace

std::unique_ptr<SequenceOut> openSequenceOut(const char* format, const char* dir, const char* name,
                                             double fps, char* err, size_t errLen, bool force) {
  if (rec::pathTooLong(dir, err, errLen)) return nullptr;
  const bool avi = std::strcmp(format, "avi") == 0;
  std::string gt;
  if (avi) {
    const size_t n = std::strlen(dir);
    gt = (n > 4 ? std::string(dir, n - 4) : std::string(dir)) + ".gt.txt";
    // A video and its ground truth are a pair: overwriting either loses a recording.
    const char* existing = rec::exists(dir) ? dir : rec::exists(gt.c_str()) ? gt.c_str() : nullptr;
    if (existing && !force) {
      std::snprintf(err, errLen,
                    "%s: already exists (--force overwrites the video and its .gt.txt)", existing);
      return nullptr;
    }
  }
  const bool dirIsNew = !avi && !rec::exists(dir);
  std::unique_ptr<SequenceOut> o = openOut(format, dir, name, fps, err, errLen);
  if (!o) return nullptr;
  if (avi) {
    o->removeFiles[0] = dir;
    o->removeFiles[1] = gt;
  } else if (dirIsNew) {
    o->removeDir = dir;  // an existing folder is not ours to remove; a new one is
  }
  return o;
}

namespace {
int failed(SequenceOut& out, const char* why, char* err, size_t errLen) {
  // The writer's own line, then what became of the partial output.
  std::snprintf(err, errLen, "%s; the partial output was removed", why);
  out.close();
  out.discard();
  return -1;
}
}  // namespace

int copySequence(FrameSource& src, SequenceOut& out, FrameSlot& slot, char* err, size_t errLen,
                 bool (*stopRequested)()) {
  int n = 0;
  for (;;) {
    if (stopRequested && stopRequested()) return failed(out, "interrupted", err, errLen);
    const ReadStatus st = src.next(slot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) return failed(out, src.error(), err, errLen);
    if (!out.write(slot)) return failed(out, out.error(), err, errLen);
    ++n;
  }
  if (!out.close()) {
    char why[512];
    std::snprintf(why, sizeof why, "%s", out.error());
    return failed(out, why, err, errLen);
  }
  return n;
}

int writeSequence(const char* tool, FrameSource& src, const char* format, const char* out,
                  const char* name, bool force, FrameSlot& slot, int* frames) {
  char err[1024] = "";
  auto sink = openSequenceOut(format, out, name, src.nominalFps(), err, sizeof err, force);
  if (!sink) {
    std::fprintf(stderr, "%s: %s\n", tool, err);
    return std::strncmp(err, "unknown format", 14) == 0 ? cli::kExitUsage : cli::kExitFailed;
  }
  platform::installStopSignals();  // an interrupted run removes its partial output
  const int n = copySequence(src, *sink, slot, err, sizeof err, platform::stopRequested);
  if (n < 0) {
    std::fprintf(stderr, "%s: %s\n", tool, err);
    return cli::kExitFailed;
  }
  *frames = n;
  return 0;
}

}  // namespace cuetrack
