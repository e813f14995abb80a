// The picture the window shows and the video records: the frame with the track drawn,
// the depth colour-mapped beside it, and two lines of text in a strip under them.
// Host builds only.
#pragma once

#include <opencv2/core.hpp>

#include "ViewTrack.hpp"

namespace cuetrack::app {

inline constexpr int kStripPx = 44;  // status text under the image

// How a track is drawn: each state in its own colour and word, so an occluded or lost
// target never looks tracked. While lost no box is drawn: the box a lost frame carries is
// where the target was last confirmed, not where it is.
struct TrackLook {
  const char* word;   // "tracking", "occluded", "lost", "searching", "idle"
  cv::Scalar colour;  // BGR, of the box, the word and the first text line
  bool drawBox;
};
TrackLook trackLook(const ViewTrack& track);

// bgr: the frame; depth16: its depth [mm] at the same size, or empty for none. The word of
// an occluded or lost track is also written on the image (at the box, or its corner).
cv::Mat overlay(const cv::Mat& bgr, const cv::Mat& depth16, const ViewTrack& track,
                const char* line1, const char* line2);

}  // namespace cuetrack::app
