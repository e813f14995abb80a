#include "RunSummary.hpp"

#include <cstdio>

namespace cuetrack::app {
void RunSummary::add(const ctp_track_t& msg, const Box* gt) {
  ++_frames;
  _procUsSum += msg.proc_us;
  if (msg.state == CTP_STATE_IDLE) {
    ++_idle;
    return;  // no target yet: nothing to score
  }
  const bool tracking = msg.state == CTP_STATE_TRACKING;
  if (tracking) {
    ++_tracked;
    _confidenceSum += msg.confidence / 65535.0;
  }
  if (gt && gt->w > 0.f && gt->h > 0.f) {
    ++_gtFrames;  // a lost frame scores 0, as in OTB's success plots
    if (tracking) {
      const Box b{static_cast<float>(msg.box_px[0]), static_cast<float>(msg.box_px[1]),
                  static_cast<float>(msg.box_px[2]), static_cast<float>(msg.box_px[3])};
      _overlapSum += overlap(b, *gt);  // intersection over union (Geometry.hpp)
    }
  }
}

void RunSummary::format(uint64_t wallUs, char* out, size_t outLen) const {
  const double s = static_cast<double>(wallUs) / 1e6;
  const double msPerFrame = _frames ? static_cast<double>(_procUsSum) / 1e3 / _frames : 0.0;
  int n = std::snprintf(
      out, outLen,
      "summary: %u frames in %.1f s (%.1f fps, %.1f ms/frame tracking), tracked %u/%u (%.0f%%)",
      _frames, s, s > 0 ? _frames / s : 0.0, msPerFrame, _tracked, _frames,
      _frames ? 100.0 * _tracked / _frames : 0.0);
  auto room = [&] { return n > 0 && static_cast<size_t>(n) < outLen; };
  if (_tracked && room()) {
    n += std::snprintf(out + n, outLen - static_cast<size_t>(n), ", mean confidence %.2f",
                       _confidenceSum / _tracked);
  }
  if (_gtFrames && room()) {
    n += std::snprintf(out + n, outLen - static_cast<size_t>(n),
                       ", ground-truth mean overlap %.2f over %u frames (a lost frame scores 0)",
                       meanOverlap(), _gtFrames);
  }
  if (_frames && _idle == _frames && room()) {
    std::snprintf(out + n, outLen - static_cast<size_t>(n), "; no target was ever given");
  }
}

}  // namespace cuetrack::app
