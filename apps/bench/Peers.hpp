// The OpenCV 4.6 contrib trackers (Debian's libopencv-contrib) that users would pick
// instead of cuetrack, behind one small interface so the bench feeds them the very
// same decoded frames. All take 8-bit BGR; none uses depth.
#pragma once

#include <memory>
#include <string>

#include <opencv2/core.hpp>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::bench {

class PeerTracker {
 public:
  virtual ~PeerTracker() = default;
  // False (with *err set) when the tracker refuses the box or throws.
  virtual bool init(const cv::Mat& bgr, const Box& box, std::string* err) = 0;
  // Returns the estimate, or an empty box when the tracker reports a failure.
  virtual Box update(const cv::Mat& bgr) = 0;
};

// Names accepted by --tracker, in the order the tables list them.
inline constexpr int kNumPeers = 7;
const char* peerName(int i);  // "opencv-kcf", ...
bool isPeerName(const std::string& name);
// nullptr (with *err) when OpenCV cannot create it.
std::unique_ptr<PeerTracker> makePeer(const std::string& name, std::string* err);

}  // namespace cuetrack::bench
