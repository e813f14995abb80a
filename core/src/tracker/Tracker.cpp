#include "cuetrack/core/tracker/Tracker.hpp"

#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/filter/SearchRegion.hpp"
#include "cuetrack/core/guards/PeakContrast.hpp"
#include "cuetrack/core/tracker/InitTarget.hpp"
#include "cuetrack/core/tracker/SpaceChoice.hpp"

namespace cuetrack {

namespace {
constexpr float kDefaultDtS = 1.f / 30.f;
float frameDtS(uint64_t last, uint64_t now) {
  if (now <= last) return kDefaultDtS;
  const float dt = static_cast<float>(now - last) * 1e-6f;
  return dt > 1.f ? 1.f : dt;
}
}  // namespace

Tracker::Tracker() = default;

ConfigError Tracker::configure(const TrackerConfig& config, uint64_t seed, const Clock* clock) {
  // Refused, not clamped: the caller says what is wrong; the tracker keeps its last one.
  if (const ConfigError e = validate(config); e != ConfigError::None) return e;
  _config = config;
  _seed = seed;
  _clock = clock;
  _space.configure(_config.adaptCylinderSize);
  _sizer.configure(tuning::cylinder::kSizeGain, tuning::cylinder::kCentreGain);
  _negatives.configure(NegativeSampler::paramsOf(_config));
  _judge.configure(_config.lostDetection, _config.occlusionGate);
  _fast.configure(_config.fastMotion);
  reset();
  return ConfigError::None;
}

void Tracker::reset() {
  _judge.reset();
  _lastBox = Box{};
}

void Tracker::addExample(const Box& win, bool positive) {
  const int slot = _set.add(_channels.tables(), win, positive);
  _cache.refreshExample(slot, _pool, _set);
}

void Tracker::addNegatives(const Box& around, int count, const PixelRect& roi) {
  NegativeSampler::Cylinder store;
  const NegativeSampler::Cylinder* cylinder =
      _space.negativesCylinder(_channels, _lastEstimate, &store);
  for (int k = 0; k < count; ++k)
    addExample(_negatives.next(k, around, roi, cylinder, _rng), false);
}

InitError Tracker::init(const Frame& frame, const Box& box) {
  _judge.stop();
  Box target;
  if (const InitError e = initTarget(frame.rgb, box, &target); e != InitError::None) return e;
  const int imageW = frame.rgb.width, imageH = frame.rgb.height;
  _padding = WindowPadding::forTarget(target);
  const Box b = _padding.toWindow(target);  // the window tracked

  const SpaceChoice space = SpaceChoice::of(_config, frame, b, _depthMedian);
  if (space.error != InitError::None) return space.error;
  _space.start(space.is3d, frame.intrinsics, imageW, imageH);
  _filterLeads = !space.is3d && _config.filterLeads2d;
  if (_filterLeads) {
    if (const InitError e = _lead.init(frame, target); e != InitError::None) return e;
    if (!_config.lostDetection) {  // dcf: nothing to judge the filter by
      _lastTimeUs = frame.timeUs;
      _judge.start(false, space.lostAfter, frame.timeUs, _space.initial(b, 0.f));
      return InitError::None;
    }
  }
  _depthFeatures = space.depthFeatures;
  _depthTables = space.depthFeatures || space.is3d;
  _fallbackWhy = space.why;
  _numWeak = space.numWeak;
  _rng.reseed(_seed);
  _reseeder.restartScan();

  const Particle q = _space.initial(b, space.surfaceMm);
  _lastEstimate = q;
  _prevEstimate = q;
  _lastBox = b;
  _space.resetSize(b);

  const PixelRect roi = clipBox(grow(b, NegativeSampler::kRange + 0.6f), imageW, imageH);
  _channels.compute(frame, roi, _depthTables);

  if (!_pool.build(_config.useGray, _depthFeatures, _config.useColour, _config.sampling, _rng))
    return InitError::BoxTooSmall;  // cannot happen with kMaxPoolFeatures (static_assert-backed)
  const int anchors = _space.initialPositives();
  _set.reset(tuning::training::kExamples, anchors);
  addExample(b, true);  // slot 0: the anchor
  for (int i = 1; i < anchors; ++i) {
    const float jitter = _space.initialJitter();
    const float s = fmath::fastExp(jitter * _rng.gaussian());
    const Box j{b.x + jitter * b.w * _rng.gaussian(), b.y + jitter * b.h * _rng.gaussian(), b.w * s,
                b.h * s};
    addExample(j, true);
  }
  addNegatives(b, _set.numNegatives() + tuning::training::kExamples, roi);  // fill the FIFO
  for (int i = 0; i < kMaxPoolFeatures; ++i) _featureErrors[i] = 0.f;
  train();
  _cue.start(_config.correlationCue, _config.correlationFilter, _space.is3d(), frame.rgb,
             _channels.tables(), b);

  _sizer.clear();
  if (_space.sizesCylinder() && frame.hasDepth()) _sizer.calibrate(frame, _channels, b, q.size[0]);
  _filter.setSize(_config.numParticles);
  _filter.fill(q);
  _lastTimeUs = frame.timeUs;
  _fast.start();
  _judge.start(space.is3d, space.lostAfter, frame.timeUs, q);
  return InitError::None;
}

void Tracker::learn(const Box& estimate, const PixelRect& roi) {
  addExample(estimate, true);
  _cue.learn(_rgb, _channels.tables(), estimate);
  addNegatives(estimate, tuning::training::kNegativesPerUpdate, roi);
  if (_config.dynamicPool && _config.sampling == FeatureSampling::Sparse) {
    const int replaced = _pool.update(_featureErrors, _rng);
    if (replaced >= 0) _cache.refreshFeature(replaced, _pool, _set);
  }
  train();
}

void Tracker::train() {
  _strong.train(_pool, _cache, _set, _numWeak, _featureErrors, tuning::training::kBoostCandidates,
                tuning::training::kAnchorWeight, tuning::training::kBoostRefreshRounds);
}

PixelRect Tracker::predict(float dtS, int framesElapsed, bool wasLost) {
  const float spread = wasLost ? tuning::kLostSpread : 1.f;
  _fast.beginFrame(_space.is3d(), dtS);
  const SearchView view = _space.view();
  const int n = _filter.size();
  _p.resize(n);
  for (int i = 0; i < n; ++i) {
    Particle& q = _filter[i];
    if (wasLost && LostSearch::drawsAnew(i))
      q = LostSearch::draw(i, _lastEstimate, _judge.lostFrames(), view, _rng);
    _space.predict(i, q, _fast, _rng, dtS, spread, framesElapsed);
    _p.boxes[i] = _space.window(q);
  }
  Box cueRegion;
  return SearchRegion::of(_p.boxes.span(), _cue.searchRegion(wasLost, _lastBox, &cueRegion),
                          _cue.scansImage(wasLost), _space.imageW(), _space.imageH());
}

bool Tracker::scorable(const Box& b, const Particle& q, bool searching) const {
  // While lost, in 3D, a window must also stand near the depth the target was last
  // confirmed at.
  return _space.scorable(b, searching) && !(searching && _judge.implausibleFind(q.p[2]));
}

void Tracker::score(const PixelRect& roi, bool wasLost) {
  const int n = _filter.size();
  for (int i = 0; i < n; ++i) _p.valid[i] = scorable(_p.boxes[i], _filter[i], wasLost) ? 1 : 0;
  _strong.evaluateMany(_channels.tables(), _p.boxes.span(), _p.valid.span(), _p.scores.span(),
                       _scanOrder.sort(_p.boxes.span(), roi.y0));
}

TrackEstimate Tracker::estimate(const CueAnswer& cue) {
  _filter.weigh(_p.scores.span(), cue.valid ? _p.cue.span() : Span<const float>{});
  // The weighted mean (the paper takes the heaviest particle: docs/experiments.md).
  TrackEstimate e;
  e.particle = _filter.weightedMean();
  e.box = _space.window(e.particle);
  const float c = e.box.empty() ? -1.f : _strong.evaluate(_channels.tables(), e.box);
  e.box = _space.filterSize(e.box);
  e.concentration = _filter.concentration(_p.boxes.span(), e.box);
  e.confidence = 0.5f * (c + 1.f);
  e.contrast = PeakContrast::kNoRing;
  if (_config.lostDetection)
    e.contrast = PeakContrast::around(
        e.box, _space.imageW(), _space.imageH(), c,
        [this](const Box& b) { return _strong.evaluate(_channels.tables(), b); });
  return e;
}

bool Tracker::decide(const Frame& frame, TrackEstimate& e, const CueAnswer& cue, bool wasLost,
                     const PixelRect& roi, bool* miss) {
  const TrackJudge::Verdict v = _judge.decide(
      e, cue, _cue.isFilter(), wasLost, TrackJudge::Sight{frame.depthMm, targetBox(e.particle)});
  *miss = v.miss;
  if (v.action == TrackJudge::Action::Learn) {
    if (_space.sizesCylinder() && frame.hasDepth() &&
        _sizer.follow(frame, _channels, _space.camera(), _space.window(e.particle), e.particle,
                      _filter))
      e.box = _space.window(e.particle);
    _lastEstimate = e.particle;
    learn(_space.sane(e.box), roi);
  } else if (v.action == TrackJudge::Action::FollowFilter) {
    _cue.follow(_rgb, _space.sane(e.box));
  }
  _judge.settle(v, frame.timeUs, e.particle, cue);
  return v.action == TrackJudge::Action::Learn;
}

void Tracker::drawAt(const Box& c, const Particle& from, float dtS, bool withVelocity) {
  const int moved =
      _reseeder.place(c, from, dtS, withVelocity, _space.view(), _channels, _rng, _filter);
  // Mostly inside the image even while tracking, as the cue's peaks are (while searching,
  // scorable() asks that already).
  const bool searching = _judge.state() == TrackState::Lost;
  _moved.resize(moved);
  for (int k = 0; k < moved; ++k) {
    const int i = _reseeder.index(k);
    _p.boxes[i] = _moved.boxes[k] = _reseeder.windows()[k];
    _moved.valid[k] = scorable(_p.boxes[i], _filter[i], searching) &&
                              (searching || _space.insideEnough(_p.boxes[i]))
                          ? 1
                          : 0;
  }
  _strong.evaluateMany(_channels.tables(), _moved.boxes.span(), _moved.valid.span(),
                       _moved.scores.span());
  for (int k = 0; k < moved; ++k)
    _p.scores[_reseeder.index(k)] = _moved.valid[k] != 0 ? _moved.scores[k] : -1.f;
}

CueAnswer Tracker::correlate(float dtS) {
  // In 3D the depth sets the scale.
  const CueAnswer a = _cue.search(_rgb, _channels.tables(), _lastBox, _space.cueSearchesScales());
  if (!a.valid) return a;
  // Some particles onto the peak, when there is one (the target may have jumped where the
  // cloud did not reach), moving on as it jumped.
  if (a.strong()) drawAt(a.box, _prevEstimate, dtS, true);
  _cue.atWindows(a, _p.boxes.span(), _p.cue.span());
  return a;
}

void Tracker::scanLost(float dtS) {
  // While lost: the cue searched over the image, a few tiles a frame at the last learnt
  // size, the tiles' best peak (if strong enough) given particles to confirm.
  if (!_cue.scanReady()) return;
  const Box last = _space.window(_lastEstimate);
  if (last.empty()) return;
  const Reseeder::Tiles tiles =
      Reseeder::tiles(last, _cue.scanStepSides(), _space.imageW(), _space.imageH());
  const Box found = _cue.scanTiles(_rgb, _channels.tables(), tiles, _reseeder);
  if (!found.empty()) drawAt(found, _lastEstimate, dtS, false);
}

TrackResult Tracker::followFilter(const Frame& frame, uint64_t t0) {
  // filterLeads2d, tracking: the background-aware filter places the box; the classifier
  // judges it there (as the particles' estimate) and learns it when the gate opens; the
  // particles wait, gathered on it, for a search if it is lost.
  const TrackResult lead = _lead.update(frame);
  if (!_config.lostDetection) return timed(lead, t0);  // dcf: the filter alone
  TrackEstimate e;
  e.box = _space.sane(_padding.toWindow(lead.box));
  e.particle = _space.initial(e.box, 0.f);
  const PixelRect roi =
      clipBox(grow(e.box, NegativeSampler::kRange + 0.6f), _space.imageW(), _space.imageH());
  _channels.compute(frame, roi, _depthTables);
  const float c = _strong.evaluate(_channels.tables(), e.box);
  e.confidence = 0.5f * (c + 1.f);
  e.concentration = 1.f;  // no cloud to disagree
  e.contrast = PeakContrast::kNoRing;
  if (_config.lostDetection)
    e.contrast = PeakContrast::around(
        e.box, _space.imageW(), _space.imageH(), c,
        [this](const Box& b) { return _strong.evaluate(_channels.tables(), b); });
  CueAnswer cue;  // the filter's peak: a low frame is a loss only once it no longer sees it
  cue.valid = true;
  cue.byLead = true;
  cue.peak = lead.confidence;
  cue.sharp = _lead.sharpness() >= tuning::lost::kLeadSharpness;
  cue.box = e.box;
  bool miss = false;
  const bool learned = decide(frame, e, cue, false, roi, &miss);
  _lastBox = e.box;
  _prevEstimate = e.particle;
  _space.resetSize(e.box);
  // Lost now: the particles, gathered on the last box, start the search next frame.
  if (_judge.state() == TrackState::Lost) _filter.fill(e.particle);
  TrackResult r;
  r.state = _judge.state();
  r.box = lead.box;
  r.confidence = e.confidence;
  r.learned = learned;
  return timed(r, t0);
}

TrackResult Tracker::timed(TrackResult r, uint64_t t0) const {
  if (_clock != nullptr) r.timesUs.total = static_cast<uint32_t>(now() - t0);
  return r;
}

TrackResult Tracker::update(const Frame& frame) {
  TrackResult r;
  r.state = _judge.state();
  if (r.state == TrackState::Idle) return r;
  r.box = _padding.toTarget(_lastBox);
  if (frame.rgb.empty() || frame.rgb.width != _space.imageW() ||
      frame.rgb.height != _space.imageH())
    return r;
  const uint64_t t0 = now();
  const float dtS = frameDtS(_lastTimeUs, frame.timeUs);
  const int framesElapsed = _fast.framesElapsed(_space.is3d(), _lastTimeUs, frame.timeUs);
  _lastTimeUs = frame.timeUs;
  const bool wasLost = _judge.beginFrame();
  _rgb = frame.rgb;
  if (_filterLeads && !wasLost) return followFilter(frame, t0);

  // Predict, and tabulate the region the particles (and negatives around them) can touch.
  const PixelRect roi = predict(dtS, framesElapsed, wasLost);
  const uint64_t t1 = now();
  _channels.compute(frame, roi, _depthTables);
  const uint64_t t2 = now();
  _space.correctDepths(frame.hasDepth(), dtS, _channels, _fast, _filter, _p.boxes.span());
  const uint64_t t3 = now();
  score(roi, wasLost);
  const CueAnswer cue = _cue.enabled() && !wasLost ? correlate(dtS) : CueAnswer{};
  if (_cue.enabled() && wasLost) scanLost(dtS);
  TrackEstimate e = estimate(cue);
  const uint64_t t4 = now();
  bool miss = false;
  const bool learned = decide(frame, e, cue, wasLost, roi, &miss);
  _judge.hold(frame.timeUs, miss, TrackJudge::Sight{frame.depthMm, targetBox(_lastEstimate)},
              &_lastEstimate);
  _fast.endFrame(learned);
  const uint64_t t5 = now();

  _filter.resample(_rng);
  if (_judge.searching(wasLost)) _filter.forgetVelocities();
  if (!e.box.empty()) {
    _lastBox = e.box;
    _prevEstimate = e.particle;
  }
  // Found again: the filter starts anew on the target where the classifier found it.
  if (_filterLeads && wasLost && _judge.state() == TrackState::Tracking && !e.box.empty())
    _lead.init(frame, _padding.toTarget(_space.sane(e.box)));

  r.box = _padding.toTarget(_lastBox);
  r.confidence = e.confidence;
  r.learned = learned;
  const bool held = _judge.report(&r);
  const Particle& at = held ? _lastEstimate : e.particle;
  if (held) r.box = targetBox(at);
  _space.report(&r, at, targetBox(at), _channels);
  if (_clock != nullptr) {
    r.timesUs.predict = static_cast<uint32_t>((t1 - t0) + (t3 - t2));
    r.timesUs.features = static_cast<uint32_t>(t2 - t1);
    r.timesUs.weigh = static_cast<uint32_t>(t4 - t3);
    r.timesUs.learn = static_cast<uint32_t>(t5 - t4);
    r.timesUs.total = static_cast<uint32_t>(now() - t0);
  }
  return r;
}

}  // namespace cuetrack
