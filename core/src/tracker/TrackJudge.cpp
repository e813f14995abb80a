#include "cuetrack/core/tracker/TrackJudge.hpp"

#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/guards/MissRule.hpp"

namespace cuetrack {

void TrackJudge::start(bool is3d, int lostAfter, uint64_t tUs, const Particle& q) {
  _is3d = is3d;
  _lost.lostAfter = lostAfter;
  _lost.reset();
  _lostFrames = 0;
  _peakLevel.reset();
  _hold.start(tUs, q);
  _depthGuard.reset(q.p[2]);
  _state = TrackState::Tracking;
}

void TrackJudge::reset() {
  _state = TrackState::Idle;
  _lost.reset();
  _lostFrames = 0;
  _hold.stop();
}

bool TrackJudge::beginFrame() {
  const bool wasLost = _state == TrackState::Lost;
  if (wasLost) ++_lostFrames;
  return wasLost;
}

bool TrackJudge::covered(const Sight& sight, const Particle& q) const {
  if (!_is3d || !_occlusionGate || sight.depthMm.empty()) return false;
  return OcclusionHold::covered(sight.depthMm, sight.targetBox, q);  // not the padded window
}

TrackJudge::Verdict TrackJudge::decide(const TrackEstimate& e, const CueAnswer& cue,
                                       bool filterTracks, bool wasLost, const Sight& sight) {
  Verdict v;
  if (_lostDetection) {
    MissRule::Inputs in;
    in.is3d = _is3d;
    in.wasLost = wasLost;
    in.onProbation = _lost.onProbation();
    in.depthMm = e.particle.p[2];
    in.contrast = e.contrast;
    // 3D, tracked last frame (the filter searches only then): what its peak says.
    const bool filterAnswered = _is3d && cue.byFilter();
    in.unlikeTarget = filterAnswered && _peakLevel.unlike(cue.peak);
    v.miss = MissRule::miss(in, _depthGuard);
    // The filter still answers like the target on the estimate (a miss stays a miss:
    // the depth or the contrast said it is not the target). In 2D with filterLeads2d the
    // estimate is the leading filter's box: its peak is the answer.
    const bool filterSees = (filterAnswered || cue.byLead) && !v.miss &&
                            (_peakLevel.like(cue.peak) || cue.sharp) &&
                            overlap(cue.box, e.box) >= tuning::lost::kOnEstimate;
    _state = _lost.step(_state, v.miss ? 0.f : e.confidence, filterSees);
    if (_state == TrackState::Lost && !wasLost) _lostFrames = 0;
  }
  // Just found again (on probation): the estimate may be off the target's centre, or
  // on a look-alike; learn only once the detector has confirmed it.
  if (!e.box.empty() && !v.miss && !_lost.onProbation() &&
      _gate.open(e.confidence, e.concentration, _state) && !covered(sight, e.particle)) {
    v.action = Action::Learn;  // only on frames fit to learn: the estimate is on the target
  } else if (filterTracks && !v.miss && !e.box.empty() && _state == TrackState::Tracking &&
             !_lost.onProbation() && !covered(sight, e.particle)) {
    // The filter follows the target on every frame it is tracked, not only on those fit
    // for the classifier: its negatives are the context itself, and a filter left behind
    // by a turning or deforming target loses it (docs/algorithm.md). Not while a nearer
    // surface covers it (3D): it would learn the occluder and follow it.
    v.action = Action::FollowFilter;
  }
  // The depth the target was last confirmed at: learnt, or found again (it may have
  // moved in depth while hidden).
  v.depthConfirmed = v.action == Action::Learn ||
                     (_state == TrackState::Tracking && (wasLost || _lost.onProbation()));
  v.state = _state;
  return v;
}

void TrackJudge::settle(const Verdict& v, uint64_t tUs, const Particle& estimate,
                        const CueAnswer& cue) {
  if (v.action == Action::Learn) {
    _hold.learnt(tUs, estimate, _is3d && _occlusionGate);
    if (cue.byFilter()) _peakLevel.learnt(cue.peak);  // on the target
  }
  if (v.depthConfirmed) _depthGuard.confirm(estimate.p[2]);
}

bool TrackJudge::hold(uint64_t tUs, bool miss, const Sight& sight, Particle* lastEstimate) {
  const bool behind = (_state == TrackState::Lost || miss) && covered(sight, *lastEstimate);
  return _hold.step(tUs, behind, lastEstimate);  // the search follows the held estimate
}

bool TrackJudge::report(TrackResult* r) const {
  r->state = _state;
  if (!_hold.holding()) return false;
  r->state = TrackState::Tracking;
  r->occluded = true;
  return true;
}

}  // namespace cuetrack
