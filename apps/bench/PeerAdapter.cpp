#include <algorithm>
#include <cmath>

#include "Peers.hpp"
#include "TrackerAdapters.hpp"

namespace cuetrack::bench {
namespace {

class PeerBench final : public BenchTracker {
 public:
  explicit PeerBench(std::string name) : _name(std::move(name)) {}

  bool init(const CachedFrame& f, const Box& box, uint64_t seed, std::string* err) override {
    if (!f.hasColour() || f.bgr.empty()) {
      *err = "cannot run: " + _name + " needs a colour image and this input has none";
      return false;
    }
    // OpenCV wants an integer box inside the image.
    const float x0 = std::max(0.f, std::floor(box.x)), y0 = std::max(0.f, std::floor(box.y));
    const float x1 = std::min(static_cast<float>(f.width), std::ceil(box.x + box.w));
    const float y1 = std::min(static_cast<float>(f.height), std::ceil(box.y + box.h));
    if (x1 - x0 < 1.f || y1 - y0 < 1.f) {
      *err = "cannot run: the initial box lies outside the image";
      return false;
    }
    cv::theRNG().state = seed;  // MIL, Boosting and TLD sample with OpenCV's RNG
    _peer = makePeer(_name, err);
    if (!_peer) return false;
    if (!_peer->init(f.bgr, Box{x0, y0, x1 - x0, y1 - y0}, err)) {
      *err = "cannot run: " + *err;
      return false;
    }
    return true;
  }

  Box update(const CachedFrame& f, double* /*stageUs*/) override { return _peer->update(f.bgr); }

 private:
  std::string _name;
  std::unique_ptr<PeerTracker> _peer;
};

}  // namespace

std::unique_ptr<BenchTracker> makePeerBench(const std::string& name, std::string* err) {
  if (!isPeerName(name)) {
    *err = "unknown tracker '" + name + "'";
    return nullptr;
  }
  return std::make_unique<PeerBench>(name);
}

}  // namespace cuetrack::bench
