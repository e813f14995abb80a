#include "cuetrack/core/tracker/FilterTracker.hpp"

#include "cuetrack/core/base/FastMath.hpp"
#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

namespace {
Box scaledAbout(const Box& b, float f) {
  const float w = b.w * f, h = b.h * f;
  return Box{b.x + 0.5f * (b.w - w), b.y + 0.5f * (b.h - h), w, h};
}
}  // namespace

InitError FilterTracker::init(const Frame& frame, const Box& box) {
  _tracking = false;
  if (frame.rgb.empty()) return InitError::NoColour;
  if (frame.rgb.width > kMaxImageWidth || frame.rgb.height > kMaxImageHeight)
    return InitError::ImageTooLarge;
  if (box.empty()) return InitError::EmptyBox;
  const float x0 = fmath::clampf(box.x, 0.f, static_cast<float>(frame.rgb.width));
  const float y0 = fmath::clampf(box.y, 0.f, static_cast<float>(frame.rgb.height));
  const float x1 = fmath::clampf(box.x + box.w, 0.f, static_cast<float>(frame.rgb.width));
  const float y1 = fmath::clampf(box.y + box.h, 0.f, static_cast<float>(frame.rgb.height));
  if (!(x1 > x0) || !(y1 > y0)) return InitError::BoxOutsideImage;
  const Box target{x0, y0, x1 - x0, y1 - y0};
  if (target.w < kMinTargetPx || target.h < kMinTargetPx) return InitError::BoxTooSmall;
  _imageW = frame.rgb.width;
  _imageH = frame.rgb.height;
  if (!_filter.reset(frame.rgb, target)) return InitError::EmptyBox;
  _box = target;
  _tracking = true;
  return InitError::None;
}

TrackResult FilterTracker::update(const Frame& frame) {
  TrackResult r;
  if (!_tracking) return r;
  r.state = TrackState::Tracking;
  r.box = _box;
  if (frame.rgb.empty() || frame.rgb.width != _imageW || frame.rgb.height != _imageH) return r;
  // The current scale first: a tie keeps the size.
  static constexpr float kFactors[kScales] = {
      1.f, 1.f / kScaleStep, kScaleStep, 1.f / (kScaleStep * kScaleStep), kScaleStep * kScaleStep};
  BackgroundAwareFilter::Answer best;
  for (int s = 0; s < kScales; ++s) {
    const Box b = scaledAbout(_box, kFactors[s]);
    if (b.w < kMinTargetPx || b.h < kMinTargetPx) continue;
    if (b.w > static_cast<float>(_imageW) || b.h > static_cast<float>(_imageH)) continue;
    const BackgroundAwareFilter::Answer a = _filter.search(frame.rgb, b);
    if (a.valid && (!best.valid || a.peak > best.peak)) best = a;
  }
  if (best.valid) {
    // The centre stays inside the image.
    const float cx =
        fmath::clampf(best.box.x + 0.5f * best.box.w, 0.f, static_cast<float>(_imageW));
    const float cy =
        fmath::clampf(best.box.y + 0.5f * best.box.h, 0.f, static_cast<float>(_imageH));
    _box = Box{cx - 0.5f * best.box.w, cy - 0.5f * best.box.h, best.box.w, best.box.h};
    _filter.learn(frame.rgb, _box, kLearnRate);
  }
  r.box = _box;
  r.confidence = fmath::clampf(best.peak, 0.f, 1.f);
  _sharpness = best.valid ? best.psr : 0.f;
  r.learned = best.valid;
  return r;
}

}  // namespace cuetrack
