// The grid snapshot on OpenCV (imgproc draws, imgcodecs writes the PNG).
#include "Snapshot.hpp"

#include <cmath>
#include <cstdio>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "CvImage.hpp"

namespace cuetrack::app {

bool writeSnapshot(const Frame& frame, const char* path, char* err, size_t errLen,
                   float xLabelScale, float yLabelScale) {
  cv::Mat img = toBgr(frame.rgb);
  const cv::Scalar line(0, 255, 255), text(255, 255, 255), shadow(0, 0, 0);
  auto label = [&](const char* s, cv::Point at) {
    cv::putText(img, s, at, cv::FONT_HERSHEY_PLAIN, 0.8, shadow, 2, cv::LINE_AA);
    cv::putText(img, s, at, cv::FONT_HERSHEY_PLAIN, 0.8, text, 1, cv::LINE_AA);
  };
  char s[16];
  for (int x = kSnapshotGridPx; x < img.cols; x += kSnapshotGridPx) {
    cv::line(img, {x, 0}, {x, img.rows - 1}, line, 1);
    std::snprintf(s, sizeof s, "%d", static_cast<int>(std::lround(x * xLabelScale)));
    label(s, {x + 2, 10});
  }
  for (int y = kSnapshotGridPx; y < img.rows; y += kSnapshotGridPx) {
    cv::line(img, {0, y}, {img.cols - 1, y}, line, 1);
    std::snprintf(s, sizeof s, "%d", static_cast<int>(std::lround(y * yLabelScale)));
    label(s, {2, y - 2});
  }
  bool ok = false;
  try {
    ok = cv::imwrite(path, img);
  } catch (const cv::Exception& e) {
    std::snprintf(err, errLen, "--snapshot %s: %s", path, e.what());
    return false;
  }
  if (!ok) {
    std::snprintf(err, errLen,
                  "--snapshot %s: cannot write (folder missing, no space, or not .png)", path);
    return false;
  }
  return true;
}

}  // namespace cuetrack::app
