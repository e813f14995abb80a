#include "cuetrack/core/filter/SearchRegion.hpp"

#include "cuetrack/core/config/Tuning.hpp"

namespace cuetrack {

PixelRect SearchRegion::of(Span<const Box> windows, const Box* cueRegion, bool wholeImage,
                           int imageW, int imageH) {
  const int n = windows.size();
  PixelRect roi{};
  float meanW = 0.f, meanH = 0.f;
  for (int i = 0; i < n; ++i) {
    if (windows[i].empty()) continue;
    meanW += windows[i].w;
    meanH += windows[i].h;
    roi = unite(roi, clipBox(windows[i], imageW, imageH));
  }
  meanW /= static_cast<float>(n);
  meanH /= static_cast<float>(n);
  constexpr float m = tuning::kRoiMarginSides;
  roi = clipBox(Box{static_cast<float>(roi.x0) - m * meanW, static_cast<float>(roi.y0) - m * meanH,
                    static_cast<float>(roi.width()) + 2.f * m * meanW,
                    static_cast<float>(roi.height()) + 2.f * m * meanH},
                imageW, imageH);
  if (cueRegion != nullptr) roi = unite(roi, clipBox(*cueRegion, imageW, imageH));
  if (wholeImage) roi = PixelRect{0, 0, imageW, imageH};
  if (roi.width() < 2 || roi.height() < 2) roi = PixelRect{0, 0, imageW, imageH};
  return roi;
}

}  // namespace cuetrack
