#include "cuetrack/core/AppearanceCue.hpp"

namespace cuetrack {

void AppearanceCue::start(bool enabled, bool filterWanted, bool templateScans, const RgbView& rgb,
                          const FrameTables& t, const Box& win) {
  _enabled = enabled;
  _filter = enabled && filterWanted;
  _template = enabled && (!_filter || templateScans);
  if (_filter) _dcf.reset(rgb, win);
  if (_template) _corr.reset(t, win);
}

}  // namespace cuetrack
