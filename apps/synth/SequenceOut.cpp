#include "SequenceOut.hpp"

#include <ftw.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>

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
}

bool SequenceOut::commit(char* err, size_t errLen) {
  for (const Move& m : moves) {
    if (m.from.empty()) continue;
    if (::rename(m.from.c_str(), m.to.c_str()) != 0) {
      std::snprintf(err, errLen, "%s: cannot move the finished output there: %s", m.to.c_str(),
                    std::strerror(errno));
      return false;
    }
  }
  if (moves[0].from.empty()) return true;
  ::rmdir(removeDir.c_str());  // the staging folder, empty now
  removeDir.clear();
  return true;
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

namespace {
// An .avi and its .gt.txt, written in a staging folder beside them (.NAME.partial-PID),
// so that a failed or interrupted run leaves the earlier files (--force) untouched and
// removes only what it made.
std::unique_ptr<SequenceOut> openStagedVideo(const char* avi, const std::string& gt,
                                             const char* name, double fps, char* err,
                                             size_t errLen) {
  const std::string path = avi;
  const size_t slash = path.find_last_of('/');
  const std::string folder = slash == std::string::npos ? "." : path.substr(0, slash + 1);
  const std::string file = slash == std::string::npos ? path : path.substr(slash + 1);
  const std::string stage = folder + (slash == std::string::npos ? "/." : ".") + file +
                            ".partial-" + std::to_string(::getpid());
  if (::mkdir(stage.c_str(), 0777) != 0) {
    std::snprintf(err, errLen, "%s: cannot create a folder beside it: %s", avi,
                  std::strerror(errno));
    return nullptr;
  }
  const std::string staged = stage + "/" + file;
  std::unique_ptr<SequenceOut> o = openOut("avi", staged.c_str(), name, fps, err, errLen);
  if (!o) {
    ::rmdir(stage.c_str());
    return nullptr;
  }
  o->removeDir = stage;
  o->moves[0] = {staged, path};
  o->moves[1] = {staged.substr(0, staged.size() - 4) + ".gt.txt", gt};
  return o;
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
  if (avi) return openStagedVideo(dir, gt, name, fps, err, errLen);
  const bool dirIsNew = !rec::exists(dir);
  std::unique_ptr<SequenceOut> o = openOut(format, dir, name, fps, err, errLen);
  if (!o) return nullptr;
  if (dirIsNew) o->removeDir = dir;  // an existing folder is not ours to remove; a new one is
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
  char why[512];
  if (!out.close()) {
    std::snprintf(why, sizeof why, "%s", out.error());
    return failed(out, why, err, errLen);
  }
  if (!out.commit(why, sizeof why)) return failed(out, why, err, errLen);
  return n;
}

int checkSequenceOut(const char* tool, const char* format, const char* out,
                     const cli::OutputGuard& inputs) {
  cli::OutputGuard guard = inputs;
  std::string clash;
  if (std::strcmp(format, "avi") == 0) {
    const size_t n = std::strlen(out);
    guard.output("--out", out);
    guard.output("--out's ground truth",
                 (n > 4 ? std::string(out, n - 4) : std::string(out)) + ".gt.txt");
  } else {
    guard.outputFolder("--out", out);
  }
  if (!guard.check(&clash)) {  // before anything is written, --force or not
    std::fprintf(stderr, "%s: %s\n", tool, clash.c_str());
    return cli::kExitUsage;
  }
  return 0;
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
