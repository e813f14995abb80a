#include "cuetrack/core/AppearanceCue.hpp"

namespace cuetrack {

void AppearanceCue::start(bool enabled, bool filterWanted, bool is3d, const RgbView& rgb,
                          const FrameTables& t, const Box& win) {
  _enabled = enabled;
  _filter = enabled && filterWanted && !is3d;
  if (_filter) _dcf.reset(rgb, win);
  if (_enabled && !_filter) _corr.reset(t, win);
}

}  // namespace cuetrack
