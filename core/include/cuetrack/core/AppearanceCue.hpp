// The track's appearance cue (beyond the paper; with `correlationCue`): the one object
// the tracker asks, whichever it is. In 2D with `correlationFilter` (RGB, or the 2D
// fallback) the correlation filter on HOG, gray and colour cells (CorrelationFilter); else
// the slowly learnt gray template (CorrelationCue): in 3D the filter cost the carried
// target (`held`) 0.9 against a seed spread of 0.7 (docs/algorithm.md).
#pragma once

#include "cuetrack/core/CorrelationCue.hpp"
#include "cuetrack/core/CorrelationFilter.hpp"
#include "cuetrack/core/Geometry.hpp"
#include "cuetrack/core/Image.hpp"
#include "cuetrack/core/IntegralChannels.hpp"
#include "cuetrack/core/Tuning.hpp"

namespace cuetrack {

class AppearanceCue {
 public:
  // The cue a new track uses (none when !enabled), first learnt on window `win`.
  void start(bool enabled, bool filterWanted, bool is3d, const RgbView& rgb, const FrameTables& t,
             const Box& win);
  bool enabled() const { return _enabled; }
  // The correlation filter, which learns on every tracked frame (Tracker::decide).
  bool isFilter() const { return _filter; }

  void learn(const RgbView& rgb, const FrameTables& t, const Box& win) {
    if (_filter) _dcf.learn(rgb, win, tuning::dcf::kLearnRate);
    if (_enabled && !_filter) _corr.learn(t, win, tuning::correlation::kLearnRate);
  }
  // scales: the filter also searches one scale step down and up (the template has one).
  bool search(const RgbView& rgb, const FrameTables& t, const Box& around, bool scales) {
    return _filter ? _dcf.search(rgb, around, scales) : _corr.search(t, around);
  }
  bool ready() const { return _filter ? _dcf.ready() : _corr.ready(); }
  float peak() const { return _filter ? _dcf.peak() : _corr.peak(); }
  Box peakBox() const { return _filter ? _dcf.peakBox() : _corr.peakBox(); }
  // The peak that is taken for the target (particles are drawn at it).
  float minPeak() const { return _filter ? tuning::dcf::kMinPeak : tuning::correlation::kMinPeak; }
  // The response at image point (u, v) of the last search's map.
  float at(float u, float v) const { return _filter ? _dcf.at(u, v) : _corr.at(u, v); }
  // The box a search around `around` reads.
  Box region(const Box& around) const {
    return _filter ? CorrelationFilter::region(around) : CorrelationCue::region(around);
  }
  // The lost scan's tile spacing [window sides]: a search covers window positions within
  // kReach cells (1.5 sides) of its centre (the filter: kPadding / 2 sides), so tiles 3
  // sides apart cover the image.
  float scanStepSides() const {
    return _filter ? CorrelationFilter::kPadding
                   : 2.f * static_cast<float>(CorrelationCue::kReach) /
                         static_cast<float>(CorrelationCue::kCells);
  }

 private:
  bool _enabled = false;
  bool _filter = false;  // this track's cue is _dcf
  CorrelationCue _corr;
  CorrelationFilter _dcf;
};

}  // namespace cuetrack
