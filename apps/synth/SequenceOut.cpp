#include "SequenceOut.hpp"

#include <cstdio>
#include <cstring>

#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/FileBuffer.hpp"
#if CUETRACK_HAVE_OPENCV
#include "cuetrack/drivers/OpenCvSources.hpp"
#endif

namespace cuetrack {

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

std::unique_ptr<SequenceOut> openSequenceOut(const char* format, const char* dir, const char* name,
                                             [[maybe_unused]] double fps, char* err,
                                             size_t errLen) {
  if (rec::pathTooLong(dir, err, errLen)) return nullptr;
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

int copySequence(FrameSource& src, SequenceOut& out, FrameSlot& slot, char* err, size_t errLen) {
  int n = 0;
  for (;;) {
    const ReadStatus st = src.next(slot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) {
      std::snprintf(err, errLen, "%s", src.error());
      return -1;
    }
    if (!out.write(slot)) {
      std::snprintf(err, errLen, "%s", out.error());
      return -1;
    }
    ++n;
  }
  if (!out.close()) {
    std::snprintf(err, errLen, "%s", out.error());
    return -1;
  }
  return n;
}

}  // namespace cuetrack
