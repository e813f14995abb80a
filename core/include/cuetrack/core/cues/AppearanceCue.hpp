// The track's appearance cue (beyond the paper; with `correlationCue`): the one object
// the tracker asks, whichever it is. With `correlationFilter` the correlation filter on
// HOG, gray and colour cells (CorrelationFilter) tracks, in 2D and in 3D; else the slowly
// learnt gray template (CorrelationCue). In 3D the filter searches the last window's
// scale only (the depth sets the scale), and the template stays beside it to scan the
// image while the target is lost. Figures: docs/algorithm.md.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/cues/CorrelationCue.hpp"
#include "cuetrack/core/cues/CorrelationFilter.hpp"
#include "cuetrack/core/filter/Reseeder.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

// What one search or scan of the cue answered: a plain value, read by the tracker and
// the verdict (TrackJudge) alike.
struct CueAnswer {
  bool valid = false;       // the map was computed (the window had something to read)
  bool byTemplate = false;  // the gray template's map (else the correlation filter's)
  // filterLeads2d: the background-aware filter placed the estimate; peak is its own,
  // sharp whether the target still stands out of its map (tuning::lost::kLeadSharpness).
  bool byLead = false;
  bool sharp = false;
  float peak = CorrelationCue::kNoResponse;  // the map's peak
  Box box{};                                 // the peak's box
  float minPeak = 0.f;  // the peak that is taken for the target (particles drawn at it)
  bool strong() const { return peak >= minPeak; }
  // The correlation filter answered (the one whose peak level says "like the target").
  bool byFilter() const { return valid && !byTemplate; }
};

class AppearanceCue {
 public:
  // The cue a new track uses (none when !enabled), first learnt on window `win`;
  // templateScans: with the filter, the template is kept to scan while lost (3D).
  void start(bool enabled, bool filterWanted, bool templateScans, const RgbView& rgb,
             const FrameTables& t, const Box& win);
  bool enabled() const { return _enabled; }
  // The correlation filter, which learns on every tracked frame (Tracker::decide).
  bool isFilter() const { return _filter; }

  // A frame fit to learn: the cue (and the scanning template) learn window `win`.
  void learn(const RgbView& rgb, const FrameTables& t, const Box& win) {
    if (_filter) _dcf.learn(rgb, win, tuning::dcf::kLearnRate);
    if (_template) _corr.learn(t, win, tuning::correlation::kLearnRate);
  }
  // Any other tracked frame: the filter follows the target (the template does not).
  void follow(const RgbView& rgb, const Box& win) {
    if (_filter) _dcf.learn(rgb, win, tuning::dcf::kLearnRate);
  }
  // Tracking: the cue around the last window; scales: the filter also searches one
  // scale step down and up (the template has one).
  CueAnswer search(const RgbView& rgb, const FrameTables& t, const Box& around, bool scales) {
    return _filter ? answer(false, _dcf.search(rgb, around, scales))
                   : answer(true, _corr.search(t, around));
  }
  // Lost: one tile of the scan, with the template when there is one.
  CueAnswer scan(const RgbView& rgb, const FrameTables& t, const Box& around) {
    return _template ? answer(true, _corr.search(t, around))
                     : answer(false, _dcf.search(rgb, around, false));
  }
  // Lost: the scan's next tiles (Reseeder::kTilesPerFrame of `tiles`, in `order`'s
  // round); the box of their best peak at least scanMinPeak(), else an empty box.
  Box scanTiles(const RgbView& rgb, const FrameTables& t, const Reseeder::Tiles& tiles,
                Reseeder& order);
  // The response at image point (u, v) of the map that gave answer `a` (valid, and the
  // last search or scan).
  float at(const CueAnswer& a, float u, float v) const {
    return a.byTemplate ? _corr.at(u, v) : _dcf.at(u, v);
  }
  // at() at the centre of each window into out (as many; an empty window: kNoResponse).
  void atWindows(const CueAnswer& a, Span<const Box> windows, Span<float> out) const;
  // Whether the tracking cue, the scanning one, has a model.
  bool trackingReady() const { return _filter ? _dcf.ready() : _corr.ready(); }
  bool scanReady() const { return _template ? _corr.ready() : _dcf.ready(); }
  // The least peak a scan's tile must reach to be taken.
  float scanMinPeak() const {
    return _template ? tuning::correlation::kMinPeak : tuning::dcf::kMinPeak;
  }
  // The box a tracking search around `around` reads.
  Box region(const Box& around) const {
    return _filter ? CorrelationFilter::region(around) : CorrelationCue::region(around);
  }
  // What this frame's search reads: tracking with a model, the region around the last
  // window `last` (written to *out and returned), else null; lost, the whole image, a
  // few tiles a frame (scansImage).
  const Box* searchRegion(bool wasLost, const Box& last, Box* out) const {
    if (!_enabled || wasLost || !trackingReady()) return nullptr;
    *out = region(last);
    return out;
  }
  bool scansImage(bool wasLost) const { return _enabled && wasLost; }
  // The lost scan's tile spacing [window sides]: a search covers window positions within
  // kReach cells (1.5 sides) of its centre (the filter: kPadding / 2 sides), so tiles 3
  // sides apart cover the image.
  float scanStepSides() const {
    return _template ? 2.f * static_cast<float>(CorrelationCue::kReach) /
                           static_cast<float>(CorrelationCue::kCells)
                     : CorrelationFilter::kPadding;
  }

 private:
  CueAnswer answer(bool byTemplate, bool valid) const {
    CueAnswer a;
    a.valid = valid;
    a.byTemplate = byTemplate;
    a.peak = byTemplate ? _corr.peak() : _dcf.peak();
    a.box = byTemplate ? _corr.peakBox() : _dcf.peakBox();
    a.minPeak = byTemplate ? tuning::correlation::kMinPeak : tuning::dcf::kMinPeak;
    return a;
  }

  bool _enabled = false;
  bool _filter = false;    // this track's cue is _dcf
  bool _template = false;  // _corr is this track's cue, or scans beside the filter
  CorrelationCue _corr;
  CorrelationFilter _dcf;
};

}  // namespace cuetrack
