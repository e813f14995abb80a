// The verdict on one update (beyond the paper's update gate): given the estimate, the
// appearance cue's answer and the track's state, the new state and whether this frame
// is a miss (MissRule, LostDetector; with `lostDetection`), what the tracker does with
// it (learn, let the correlation filter follow the target, or nothing: UpdateGate and
// the occluder check of `occlusionGate`), whether the target's depth is confirmed
// (DepthGuard), and the hold behind an occluder (OcclusionHold) that overrides the
// result. It owns these small components and the track's state; it sees no frame,
// only the values the tracker hands it.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack/core/cues/AppearanceCue.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/guards/DepthGuard.hpp"
#include "cuetrack/core/guards/Gate.hpp"
#include "cuetrack/core/guards/OcclusionHold.hpp"
#include "cuetrack/core/guards/PeakLevel.hpp"

namespace cuetrack {

// One update's estimate: the particle (3D: the cylinder), its window, and what the
// verdict judges it by.
struct TrackEstimate {
  Particle particle{};
  Box box{};
  float confidence = 0.f;     // (c + 1) / 2 at the estimate
  float concentration = 0.f;  // weighted mean overlap of the particles with it
  float contrast = 0.f;       // PeakContrast: the score above the windows around it
};

class TrackJudge {
 public:
  enum class Action : uint8_t {
    None,          // nothing learnt
    Learn,         // a frame fit to learn: classifier, training set, appearance cue
    FollowFilter,  // tracked but not fit for the classifier: the filter alone follows
  };
  struct Verdict {
    TrackState state = TrackState::Idle;
    bool miss = false;  // not the target, whatever the confidence: not learnt
    Action action = Action::None;
    bool depthConfirmed = false;  // the estimate's depth is the target's (DepthGuard)
  };
  // What the verdict reads of the frame besides the estimate: its depth (empty: none)
  // and the estimate's own box (less the small-target padding), for the occluder check.
  struct Sight {
    DepthView depthMm{};
    Box targetBox{};
  };

  void configure(bool lostDetection, bool occlusionGate) {
    _lostDetection = lostDetection;
    _occlusionGate = occlusionGate;
  }
  // A new track at q (time tUs) in 2D or 3D, lost after `lostAfter` low frames: Tracking.
  void start(bool is3d, int lostAfter, uint64_t tUs, const Particle& q);
  void stop() { _state = TrackState::Idle; }  // no track (an init under way)
  void reset();                               // back to Idle, the lost count cleared
  TrackState state() const { return _state; }
  // Before an update: whether the target was lost, counting the frames it has been.
  bool beginFrame();
  int lostFrames() const { return _lostFrames; }  // since it was declared lost
  // After the verdict: searching, or just found (wasLost), so the particles' velocities,
  // including the jumps the depth correction gave search particles, are forgotten.
  bool searching(bool wasLost) const { return _state == TrackState::Lost || wasLost; }

  // Lost detection, the update gate and the follow rule on estimate e; wasLost: from
  // beginFrame(); filterTracks: the track's cue is the correlation filter.
  Verdict decide(const TrackEstimate& e, const CueAnswer& cue, bool filterTracks, bool wasLost,
                 const Sight& sight);
  // After the verdict's action ran: `estimate` as learnt (the cylinder sizer may have
  // moved it), feeding the hold's motion and the filter's peak level; its depth confirmed.
  void settle(const Verdict& v, uint64_t tUs, const Particle& estimate, const CueAnswer& cue);
  // The hold behind an occluder, at time tUs: lost or missed, with the last learnt
  // estimate covered (sight: its own box), *lastEstimate is moved where the target is
  // held. Returns whether it is held.
  bool hold(uint64_t tUs, bool miss, const Sight& sight, Particle* lastEstimate);
  // The result's state; while held, Tracking and occluded. Returns whether held (the
  // result then reports the held estimate).
  bool report(TrackResult* r) const;

  // 3D with occlusionGate: q's own box is mostly covered by a nearer surface.
  bool covered(const Sight& sight, const Particle& q) const;
  // 3D with lostDetection: a find at depth zMm too far off the confirmed depth.
  bool implausibleFind(float zMm) const {
    return _is3d && _lostDetection && _depthGuard.implausibleFind(zMm);
  }

 private:
  bool _lostDetection = false, _occlusionGate = false, _is3d = false;
  TrackState _state = TrackState::Idle;
  int _lostFrames = 0;  // frames since declared lost
  UpdateGate _gate{};
  LostDetector _lost{};
  DepthGuard _depthGuard;  // 3D: the estimate's depth against the confirmed one
  PeakLevel _peakLevel;    // the filter's peak on the target (3D: found again?)
  // occlusionGate: lost while covered by a nearer surface, the target is reported where
  // it is held; the last estimate follows, and the search with it.
  OcclusionHold _hold;
};

}  // namespace cuetrack
