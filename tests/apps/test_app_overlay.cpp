// What the window and the video draw for each state (Overlay): tracking, occluded and lost
// each in their own colour and word; no box while lost (the box a lost frame carries is
// where the target was last confirmed, not where it is).
#include <catch2/catch.hpp>

#include <opencv2/core.hpp>
#include <string>

#include "Overlay.hpp"
#include "cuetrack_proto.h"

using namespace cuetrack;
using namespace cuetrack::app;

namespace {

constexpr int kW = 200, kH = 120;
const cv::Rect kBox(60, 50, 40, 30);

cv::Mat draw(uint8_t state, uint8_t flags) {
  const cv::Mat grey(kH, kW, CV_8UC3, cv::Scalar(90, 90, 90));
  ViewTrack t;
  t.state = state;
  t.flags = flags;
  t.box = Box{static_cast<float>(kBox.x), static_cast<float>(kBox.y),
              static_cast<float>(kBox.width), static_cast<float>(kBox.height)};
  t.confidence = 0.5f;
  return overlay(grey, cv::Mat(), t, trackLook(t).word, "");
}

// Pixels of exactly colour on the box's outline (its left and right edges).
int onOutline(const cv::Mat& img, const cv::Scalar& colour) {
  const cv::Vec3b c(static_cast<uint8_t>(colour[0]), static_cast<uint8_t>(colour[1]),
                    static_cast<uint8_t>(colour[2]));
  int n = 0;
  for (int y = kBox.y + 2; y < kBox.y + kBox.height - 2; ++y)
    n += (img.at<cv::Vec3b>(y, kBox.x) == c) + (img.at<cv::Vec3b>(y, kBox.x + kBox.width) == c);
  return n;
}

// Pixels of the image (not the strip) that are strongly of a colour's hue: red or magenta.
int reddish(const cv::Mat& img, bool magenta) {
  int n = 0;
  for (int y = 0; y < kH; ++y)
    for (int x = 0; x < kW; ++x) {
      const cv::Vec3b p = img.at<cv::Vec3b>(y, x);
      n += p[2] > 200 && p[1] < 60 && (magenta ? p[0] > 200 : p[0] < 60);
    }
  return n;
}

}  // namespace

TEST_CASE("each state is drawn in its own colour and word; lost draws no box") {
  const ViewTrack tracking{0, CTP_STATE_TRACKING, 0, {}, 1.f};
  const ViewTrack occluded{0, CTP_STATE_TRACKING, CTP_FLAG_OCCLUDED, {}, 1.f};
  const ViewTrack lost{0, CTP_STATE_LOST, 0, {}, 1.f};
  const ViewTrack searching{0, CTP_STATE_SEARCHING, 0, {}, 1.f};
  CHECK(std::string(trackLook(tracking).word) == "tracking");
  CHECK(std::string(trackLook(occluded).word) == "occluded");
  CHECK(std::string(trackLook(lost).word) == "lost");
  CHECK(std::string(trackLook(searching).word) == "searching");
  CHECK(trackLook(occluded).colour != trackLook(tracking).colour);
  CHECK(trackLook(lost).colour != trackLook(tracking).colour);
  CHECK(trackLook(lost).colour != trackLook(occluded).colour);

  // Tracking: the box in green, no other word on the image.
  const cv::Mat t = draw(CTP_STATE_TRACKING, 0);
  CHECK(t.rows == kH + kStripPx);
  CHECK(onOutline(t, trackLook(tracking).colour) > 40);
  CHECK(reddish(t, false) == 0);
  CHECK(reddish(t, true) == 0);
  // Occluded: the box in its own colour, never green, and "occluded" written by it.
  const cv::Mat o = draw(CTP_STATE_TRACKING, CTP_FLAG_OCCLUDED);
  CHECK(onOutline(o, trackLook(occluded).colour) > 40);
  CHECK(onOutline(o, trackLook(tracking).colour) == 0);
  CHECK(reddish(o, true) > 40);  // the box and the word
  // Lost and searching: no box at all (the outline stays the frame's grey), "target lost"
  // written in red on the image.
  for (const uint8_t state : {uint8_t{CTP_STATE_LOST}, uint8_t{CTP_STATE_SEARCHING}}) {
    INFO("state " << int{state});
    const cv::Mat l = draw(state, 0);
    CHECK(onOutline(l, cv::Scalar(90, 90, 90)) == 2 * (kBox.height - 4));
    CHECK(reddish(l, false) > 20);
  }
}
