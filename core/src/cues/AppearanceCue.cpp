#include "cuetrack/core/cues/AppearanceCue.hpp"

namespace cuetrack {

void AppearanceCue::start(bool enabled, bool filterWanted, bool templateScans, const RgbView& rgb,
                          const FrameTables& t, const Box& win) {
  _enabled = enabled;
  _filter = enabled && filterWanted;
  _template = enabled && (!_filter || templateScans);
  if (_filter) _dcf.reset(rgb, win);
  if (_template) _corr.reset(t, win);
}

Box AppearanceCue::scanTiles(const RgbView& rgb, const FrameTables& t, const Reseeder::Tiles& tiles,
                             Reseeder& order) {
  float best = scanMinPeak();
  Box found{};
  for (int j = 0; j < Reseeder::kTilesPerFrame && j < tiles.count(); ++j) {
    const CueAnswer a = scan(rgb, t, order.nextTile(tiles));
    if (a.valid && a.peak >= best) {
      best = a.peak;
      found = a.box;
    }
  }
  return found;
}

void AppearanceCue::atWindows(const CueAnswer& a, Span<const Box> windows, Span<float> out) const {
  for (int i = 0; i < windows.size(); ++i) {
    const Box& b = windows[i];
    const float u = b.x + 0.5f * b.w, v = b.y + 0.5f * b.h;
    out[i] = b.empty() ? CorrelationCue::kNoResponse : at(a, u, v);
  }
}

}  // namespace cuetrack
