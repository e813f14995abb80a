#include "Peers.hpp"

#include <opencv2/tracking.hpp>
#include <opencv2/tracking/tracking_legacy.hpp>
#include <opencv2/video/tracking.hpp>

namespace cuetrack::bench {
namespace {

const char* const kPeerNames[kNumPeers] = {"opencv-kcf",      "opencv-csrt",       "opencv-mil",
                                           "opencv-boosting", "opencv-medianflow", "opencv-mosse",
                                           "opencv-tld"};

Box toBox(double x, double y, double w, double h) {
  return Box{static_cast<float>(x), static_cast<float>(y), static_cast<float>(w),
             static_cast<float>(h)};
}

// The current API (cv::Tracker: KCF, CSRT, MIL).
class ModernPeer final : public PeerTracker {
 public:
  explicit ModernPeer(cv::Ptr<cv::Tracker> t) : _t(std::move(t)) {}
  bool init(const cv::Mat& bgr, const Box& box, std::string* err) override {
    try {
      _t->init(bgr, cv::Rect(cvRound(box.x), cvRound(box.y), cvRound(box.w), cvRound(box.h)));
      return true;
    } catch (const cv::Exception& e) {
      *err = std::string("OpenCV refused the initial box: ") + e.what();
      return false;
    }
  }
  Box update(const cv::Mat& bgr) override {
    cv::Rect r;
    try {
      if (!_t->update(bgr, r)) return Box{};
    } catch (const cv::Exception&) {
      return Box{};  // counted as a lost frame
    }
    return toBox(r.x, r.y, r.width, r.height);
  }

 private:
  cv::Ptr<cv::Tracker> _t;
};

// The legacy API (cv::legacy::Tracker: Boosting, MedianFlow, MOSSE, TLD).
class LegacyPeer final : public PeerTracker {
 public:
  explicit LegacyPeer(cv::Ptr<cv::legacy::Tracker> t) : _t(std::move(t)) {}
  bool init(const cv::Mat& bgr, const Box& box, std::string* err) override {
    try {
      if (_t->init(bgr, cv::Rect2d(box.x, box.y, box.w, box.h))) return true;
      *err = "OpenCV refused the initial box";
    } catch (const cv::Exception& e) {
      *err = std::string("OpenCV refused the initial box: ") + e.what();
    }
    return false;
  }
  Box update(const cv::Mat& bgr) override {
    cv::Rect2d r;
    try {
      if (!_t->update(bgr, r)) return Box{};
    } catch (const cv::Exception&) {
      return Box{};
    }
    return toBox(r.x, r.y, r.width, r.height);
  }

 private:
  cv::Ptr<cv::legacy::Tracker> _t;
};

}  // namespace

const char* peerName(int i) {
  return i >= 0 && i < kNumPeers ? kPeerNames[i] : nullptr;
}

bool isPeerName(const std::string& name) {
  for (const char* n : kPeerNames)
    if (name == n) return true;
  return false;
}

std::unique_ptr<PeerTracker> makePeer(const std::string& name, std::string* err) {
  try {
    if (name == "opencv-kcf") return std::make_unique<ModernPeer>(cv::TrackerKCF::create());
    if (name == "opencv-csrt") return std::make_unique<ModernPeer>(cv::TrackerCSRT::create());
    if (name == "opencv-mil") return std::make_unique<ModernPeer>(cv::TrackerMIL::create());
    if (name == "opencv-boosting")
      return std::make_unique<LegacyPeer>(cv::legacy::TrackerBoosting::create());
    if (name == "opencv-medianflow")
      return std::make_unique<LegacyPeer>(cv::legacy::TrackerMedianFlow::create());
    if (name == "opencv-mosse")
      return std::make_unique<LegacyPeer>(cv::legacy::TrackerMOSSE::create());
    if (name == "opencv-tld") return std::make_unique<LegacyPeer>(cv::legacy::TrackerTLD::create());
  } catch (const cv::Exception& e) {
    *err = name + ": OpenCV cannot create it: " + e.what();
    return nullptr;
  }
  *err = "unknown tracker '" + name + "'";
  return nullptr;
}

}  // namespace cuetrack::bench
