#include "CvImage.hpp"

namespace cuetrack::app {

cv::Mat toBgr(const RgbView& rgb) {
  cv::Mat bgr(rgb.height, rgb.width, CV_8UC3);
  for (int y = 0; y < rgb.height; ++y) {
    const Rgb8* s = rgb.row(y);
    uint8_t* d = bgr.ptr<uint8_t>(y);
    for (int x = 0; x < rgb.width; ++x) {
      d[3 * x] = s[x].b;
      d[3 * x + 1] = s[x].g;
      d[3 * x + 2] = s[x].r;
    }
  }
  return bgr;
}

}  // namespace cuetrack::app
