// TrackJudge: the verdict on one update, from values alone (no frame, no tracker): the
// state and the miss, the action (learn, the filter follows, nothing), the depth
// confirmed, and the hold behind an occluder that overrides the result.
#include <catch2/catch.hpp>

#include <cstdint>

#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/tracker/TrackJudge.hpp"

using namespace cuetrack;

namespace {
constexpr int W = 40, H = 30;
uint16_t gDepth[W * H];

Particle at3d(float zMm) {
  Particle q;
  q.p = Eigen::Vector3f(0.f, 0.f, zMm);
  q.size = Eigen::Vector2f(200.f, 300.f);
  return q;
}

// An estimate at depth zMm with the given confidence, a concentrated cloud, contrast.
TrackEstimate estimate(float zMm, float confidence, float contrast = 1.f) {
  TrackEstimate e;
  e.particle = at3d(zMm);
  e.box = Box{10.f, 10.f, 10.f, 10.f};
  e.confidence = confidence;
  e.concentration = 0.9f;
  e.contrast = contrast;
  return e;
}

// The frame's depth: every pixel at zMm (0: no depth).
TrackJudge::Sight sight(uint16_t zMm) {
  for (uint16_t& d : gDepth) d = zMm;
  TrackJudge::Sight s;
  if (zMm > 0) s.depthMm = DepthView{gDepth, W, H, W};
  s.targetBox = Box{10.f, 10.f, 10.f, 10.f};
  return s;
}

TrackJudge started(bool is3d, bool lostDetection, bool occlusionGate) {
  TrackJudge j;
  j.configure(lostDetection, occlusionGate);
  j.start(is3d, tuning::lost::kLostAfter, 0, at3d(1500.f));
  return j;
}
}  // namespace

TEST_CASE("TrackJudge: a confident estimate is learnt, a low one lost after lostAfter",
          "[core][judge]") {
  TrackJudge j = started(true, true, false);
  CHECK(j.state() == TrackState::Tracking);
  CueAnswer none;
  TrackJudge::Verdict v = j.decide(estimate(1500.f, 0.9f), none, false, j.beginFrame(), sight(0));
  CHECK(v.action == TrackJudge::Action::Learn);
  CHECK(v.depthConfirmed);
  CHECK_FALSE(v.miss);
  for (int k = 0; k < tuning::lost::kLostAfter; ++k) {
    v = j.decide(estimate(1500.f, 0.1f), none, false, j.beginFrame(), sight(0));
    CHECK(v.action == TrackJudge::Action::None);
  }
  CHECK(v.state == TrackState::Lost);
  CHECK(j.state() == TrackState::Lost);
  CHECK(j.beginFrame());  // was lost: one frame counted
  CHECK(j.lostFrames() == 1);
  TrackResult r;
  CHECK_FALSE(j.report(&r));
  CHECK(r.state == TrackState::Lost);
}

TEST_CASE("TrackJudge: a flat estimate or a depth jump is a miss, never learnt", "[core][judge]") {
  TrackJudge j = started(true, true, false);
  CueAnswer none;
  TrackJudge::Verdict v =
      j.decide(estimate(1500.f, 0.9f, 0.f), none, false, j.beginFrame(), sight(0));
  CHECK(v.miss);
  CHECK(v.action == TrackJudge::Action::None);
  v = j.decide(estimate(600.f, 0.9f), none, false, j.beginFrame(), sight(0));  // jumped
  CHECK(v.miss);
  // Without lost detection, the same frame is learnt.
  TrackJudge off = started(true, false, false);
  v = off.decide(estimate(600.f, 0.9f), none, false, off.beginFrame(), sight(0));
  CHECK_FALSE(v.miss);
  CHECK(v.action == TrackJudge::Action::Learn);
  // implausibleFind is 3D and lost detection's.
  CHECK(j.implausibleFind(5000.f));
  CHECK_FALSE(off.implausibleFind(5000.f));
  CHECK_FALSE(started(false, true, false).implausibleFind(5000.f));
}

TEST_CASE("TrackJudge: the filter follows a tracked frame the classifier may not learn",
          "[core][judge]") {
  TrackJudge j = started(false, true, false);
  CueAnswer none;
  TrackEstimate e = estimate(0.f, 0.5f);  // under the gate's confidence, not yet lost
  TrackJudge::Verdict v = j.decide(e, none, true, j.beginFrame(), sight(0));
  CHECK(v.action == TrackJudge::Action::FollowFilter);
  CHECK_FALSE(v.depthConfirmed);
  v = j.decide(e, none, false, j.beginFrame(), sight(0));  // the template does not follow
  CHECK(v.action == TrackJudge::Action::None);
}

TEST_CASE("TrackJudge: covered by a nearer surface, nothing is learnt and the target is held",
          "[core][judge]") {
  TrackJudge j = started(true, true, true);
  CueAnswer none;
  CHECK_FALSE(j.covered(sight(0), at3d(1500.f)));  // no depth: never covered
  const TrackJudge::Sight near = sight(500);       // a surface a metre in front of the target
  CHECK(j.covered(near, at3d(1500.f)));
  TrackJudge::Verdict v = j.decide(estimate(1500.f, 0.9f), none, true, j.beginFrame(), near);
  CHECK(v.action == TrackJudge::Action::None);
  Particle last = at3d(1500.f);
  CHECK(j.hold(1000, true, near, &last));  // missed and covered: held
  TrackResult r;
  r.state = TrackState::Lost;
  CHECK(j.report(&r));
  CHECK(r.state == TrackState::Tracking);
  CHECK(r.occluded);
  // 2D, or without occlusionGate: never covered.
  CHECK_FALSE(started(false, true, true).covered(near, at3d(1500.f)));
  CHECK_FALSE(started(true, true, false).covered(near, at3d(1500.f)));
  CHECK_FALSE(j.hold(2000, false, sight(0), &last));  // uncovered: no longer held
}

TEST_CASE("TrackJudge: the filter's peak, once learnt, judges a find on probation",
          "[core][judge]") {
  TrackJudge j = started(true, true, false);
  CueAnswer filter;
  filter.valid = true;
  filter.peak = 0.8f;
  filter.box = Box{10.f, 10.f, 10.f, 10.f};
  TrackJudge::Verdict v = j.decide(estimate(1500.f, 0.9f), filter, true, j.beginFrame(), sight(0));
  REQUIRE(v.action == TrackJudge::Action::Learn);
  j.settle(v, 0, at3d(1500.f), filter);  // the peak level learns 0.8
  // Lost, then found again: on probation, a low filter peak is a miss.
  for (int k = 0; k < tuning::lost::kLostAfter; ++k)
    j.decide(estimate(1500.f, 0.1f), CueAnswer{}, true, j.beginFrame(), sight(0));
  REQUIRE(j.state() == TrackState::Lost);
  for (int k = 0; k < tuning::lost::kFoundAfter; ++k)
    v = j.decide(estimate(1500.f, 0.95f), CueAnswer{}, true, j.beginFrame(), sight(0));
  REQUIRE(j.state() == TrackState::Tracking);  // found: on probation, not learnt
  CHECK(v.action == TrackJudge::Action::None);
  CHECK(v.depthConfirmed);  // found again: its depth is the target's
  CueAnswer low = filter;
  low.peak = 0.1f;
  v = j.decide(estimate(1500.f, 0.95f), low, true, j.beginFrame(), sight(0));
  CHECK(v.miss);
}
