// The tracker's public face. The implementation (core/src/) owns every buffer by
// value; construct once (static storage or one allocation at start-up), then
// init/update never allocate, never throw.
//
// Contract for every user (apps, tests, bench):
//   static Tracker tracker;                       // ~MiBs: not on the stack
//   if (tracker.configure(config, seed, &clock) != ConfigError::None) ...  // refused
//   if (tracker.init(frame, box) != InitError::None) ...
//   TrackResult r = tracker.update(nextFrame);
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/base/TrackResult.hpp"
#include "cuetrack/core/config/ConfigError.hpp"
#include "cuetrack/core/config/InitError.hpp"
#include "cuetrack/core/config/TrackerConfig.hpp"
#include "cuetrack/core/cues/AppearanceCue.hpp"
#include "cuetrack/core/cues/CylinderSizer.hpp"
#include "cuetrack/core/cues/DepthMedian.hpp"
#include "cuetrack/core/filter/FastMotion.hpp"
#include "cuetrack/core/filter/LostSearch.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/filter/ParticleScratch.hpp"
#include "cuetrack/core/filter/Reseeder.hpp"
#include "cuetrack/core/model/FeaturePool.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"
#include "cuetrack/core/model/NegativeSampler.hpp"
#include "cuetrack/core/model/ScanOrder.hpp"
#include "cuetrack/core/model/StrongClassifier.hpp"
#include "cuetrack/core/model/TrainingSet.hpp"
#include "cuetrack/core/tracker/FilterTracker.hpp"
#include "cuetrack/core/tracker/Space.hpp"
#include "cuetrack/core/tracker/TrackJudge.hpp"
#include "cuetrack/core/tracker/WindowPadding.hpp"

namespace cuetrack {

// The members are components (particle filter, observation model, feature pool,
// training set, negative sampler, and the beyond-the-paper state space, verdict,
// cylinder sizer, fast motion, appearance cue and reseeder), each a fixed-size class of
// its own with its own tests; Tracker wires them: the verdict (TrackJudge) keeps the
// track's state, the state space (Space) everything that differs between 2D and 3D.
// It is large (MiBs): give it static storage or allocate it once.
class Tracker {
 public:
  Tracker();

  // Chooses the configuration, the random seed and an optional clock for stage timings.
  // An invalid configuration (validate()) is refused with its reason, and the tracker
  // keeps the one it had.
  [[nodiscard]] ConfigError configure(const TrackerConfig& config, uint64_t seed,
                                      const Clock* clock = nullptr);
  InitError init(const Frame& frame, const Box& box);
  TrackResult update(const Frame& frame);
  void reset();  // back to Idle; keeps the configuration
  const TrackerConfig& config() const { return _config; }

  // Whether the running track uses the 3D state / depth features (after any fallback).
  bool uses3d() const { return _space.is3d(); }
  bool usesDepthFeatures() const { return _depthFeatures; }
  // Why a track that asked for 3D or depth runs 2D RGB (SpaceChoice); None: as asked.
  InitError fallbackReason() const { return _fallbackWhy; }
  // Read-only views of the components, for tests and diagnostics.
  const FeaturePool& pool() const { return _pool; }
  const TrainingSet& trainingSet() const { return _set; }
  const StrongClassifier& classifier() const { return _strong; }
  const ParticleFilter& particles() const { return _filter; }

 private:
  // update()'s stages, in order.
  PixelRect predict(float dtS, int framesElapsed,
                    bool wasLost);                 // motion (+ search while lost); the ROI
  void score(const PixelRect& roi, bool wasLost);  // every particle's classifier score
  // correlationCue: the cue's map; some particles at its peak. Its answer (invalid when none).
  CueAnswer correlate(float dtS);
  void scanLost(float dtS);  // ... while lost: the template over the image, tile by tile
  // One particle in correlation::kEvery drawn at window c from `from` (Reseeder), and scored.
  void drawAt(const Box& c, const Particle& from, float dtS, bool withVelocity);
  // Whether particle q's window b is scored (else -1). While searching (lost) it must lie
  // mostly inside the image and, in 3D, not on a surface too far off the confirmed depth
  // (DepthGuard::implausibleFind): the cloud would gather on a look-alike or a texture
  // there that it could never confirm.
  bool scorable(const Box& b, const Particle& q, bool searching) const;
  TrackEstimate estimate(const CueAnswer& cue);  // weights (with the cue's map) and the estimate
  // filterLeads2d, tracking: the filter's box, judged and learnt by the classifier.
  TrackResult followFilter(const Frame& frame, uint64_t t0);
  TrackResult timed(TrackResult r, uint64_t t0) const;  // with its total time, if clocked
  // The verdict (TrackJudge) and its action; true when learnt, *miss: the frame missed.
  bool decide(const Frame& frame, TrackEstimate& e, const CueAnswer& cue, bool wasLost,
              const PixelRect& roi, bool* miss);

  uint64_t now() const { return _clock != nullptr ? _clock->nowUs() : 0; }
  // The target's own box of particle q: its window less any small-target padding.
  Box targetBox(const Particle& q) const { return _padding.toTarget(_space.window(q)); }
  void addNegatives(const Box& around, int count, const PixelRect& roi);
  void addExample(const Box& win, bool positive);
  void learn(const Box& estimate, const PixelRect& roi);
  void train();  // GentleBoost on the training set

  TrackerConfig _config{};
  uint64_t _seed = 0;
  const Clock* _clock = nullptr;
  Rng _rng{};
  TrackJudge _judge;  // the state, the miss, what to learn, the hold
  Space _space;       // 2D or 3D, chosen at init: windows, motion, the initial particle
  bool _depthFeatures = false;
  bool _depthTables = false;  // the integral tables hold depth (depth features, or 3D)
  InitError _fallbackWhy = InitError::None;
  int _numWeak = 1;  // M for this track: numWeakClassifiers, or ...2d in the 2D fallback
  uint64_t _lastTimeUs = 0;
  FastMotion _fast{};        // fastMotion: jumping particles, coasting over dropped frames
  Box _lastBox{};            // the window tracked (padded for a small target)
  WindowPadding _padding{};  // target -> window, for a target under kMinTrackedSidePx
  Particle _lastEstimate{};
  Particle _prevEstimate{};  // the last frame's estimate (correlate() moves it)
  AppearanceCue _cue;        // correlationCue: the filter (and template), or the template
  RgbView _rgb{};            // update()'s colour image, for the filter
  Reseeder _reseeder;        // particles at the cue's peak; the lost scan's tiles
  WindowScratch<Reseeder::kMaxMoved> _moved;  // ... their windows and scores

  IntegralChannels _channels;
  FeaturePool _pool;
  TrainingSet _set;
  ResponseCache _cache;
  StrongClassifier _strong;
  ParticleFilter _filter;
  ParticleScratch _p;  // this update's windows, scores and the cue's map, per particle
  ScanOrder _scanOrder;
  float _featureErrors[kMaxPoolFeatures];
  NegativeSampler _negatives{};
  CylinderSizer _sizer{};    // adaptCylinderSize: D, H and the centre follow the depth silhouette
  DepthMedian _depthMedian;  // where a new 3D track stands
  // filterLeads2d: a 2D track's box is the background-aware filter's.
  FilterTracker _lead;
  bool _filterLeads = false;
};
// Everything together (Config.hpp's list of big buffers plus the small ones): 13,411,256 B
// on x86-64 at 640x480 (docs/benchmarks.md), within the 16 MiB.
static_assert(sizeof(Tracker) <= kTrackerBudgetBytes, "the tracker must fit its 16 MiB budget");

}  // namespace cuetrack
