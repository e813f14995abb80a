#include "cuetrack/drivers/RecordedReader.hpp"

#include <cstdio>

#include "cuetrack/drivers/FileBuffer.hpp"

namespace cuetrack {

CameraIntrinsics kinectIntrinsicsScaled(int widthPx, int heightPx) {
  const float sx = static_cast<float>(widthPx) / 640.f;
  const float sy = static_cast<float>(heightPx) / 480.f;
  return {kKinectV1Intrinsics.fx * sx, kKinectV1Intrinsics.fy * sy, kKinectV1Intrinsics.cx * sx,
          kKinectV1Intrinsics.cy * sy};
}

void RecordedReader::restart(const SourceOptions& opt) {
  _opt = opt;
  _gt = GroundTruth{};
  _next = _emitted = _skipped = 0;
  _width = _height = 0;
  _error[0] = '\0';
  _warning[0] = '\0';
}

bool RecordedReader::loadGroundTruth(const std::string& besidePath, GtFormat format, int frames,
                                     const char* framesNoun) {
  const std::string path = _opt.gtPath ? std::string(_opt.gtPath) : besidePath;
  if (!_opt.gtPath && !rec::exists(path.c_str())) return true;
  bool ok = _gt.load(path.c_str(), format, _error, sizeof _error);
  if (ok && frames > 0 && _gt.count() != frames && _gt.count() != frames - 1) {
    std::snprintf(_error, sizeof _error, "%s: %d ground-truth boxes for %d %s", path.c_str(),
                  _gt.count(), frames, framesNoun);
    ok = false;
  }
  if (ok || !_opt.groundTruthOptional || _opt.gtPath) return ok;
  // Not needed for the target: a file of another kind beside the video is no reason to stop.
  std::snprintf(_warning, sizeof _warning, "%.600s; not used as ground truth (no score)", _error);
  _error[0] = '\0';
  _gt = GroundTruth{};
  return true;
}

ReadStatus RecordedReader::next(FrameSlot& out) {
  for (;;) {
    if (_opt.maxFrames >= 0 && _emitted >= _opt.maxFrames) return ReadStatus::End;
    const int i = _next;
    out.scale = FrameScale{};  // a reader that scales its frame down says so in readFrame
    const FrameRead r = readFrame(i, out);
    if (r == FrameRead::End) return ReadStatus::End;
    if (r == FrameRead::Error) return ReadStatus::Error;
    ++_next;
    if (r == FrameRead::Bad) {
      if (!_opt.skipBadFrames) return ReadStatus::Error;
      ++_skipped;
      continue;
    }
    // The source's own size: ground truth is in its pixels, mapped to the slot's.
    const int sourceW = out.scale.sourceWidth(out.rgb.width());
    const int sourceH = out.scale.sourceHeight(out.rgb.height());
    if (_width == 0) {
      _width = sourceW;
      _height = sourceH;
    }
    out.index = i;
    out.timeUs = frameTimeUs(i);
    out.intrinsics = frameIntrinsics(out.rgb.width(), out.rgb.height());
    Box truth{};
    out.hasGroundTruth = _gt.boxAt(i, sourceW, sourceH, &truth);
    out.groundTruth = out.hasGroundTruth && !truth.empty() ? out.scale.toSlot(truth) : Box{};
    ++_emitted;
    return ReadStatus::Ok;
  }
}

}  // namespace cuetrack
