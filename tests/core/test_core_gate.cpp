// The update gate and the lost detector (Gate.hpp).
#include <catch2/catch.hpp>

#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/guards/Gate.hpp"

using namespace cuetrack;

TEST_CASE("the update gate opens only on a confident, concentrated, tracked estimate",
          "[core][gate]") {
  const UpdateGate g;  // 0.55 / 0.5
  CHECK(g.open(0.55f, 0.5f, TrackState::Tracking));
  CHECK_FALSE(g.open(0.54f, 0.9f, TrackState::Tracking));
  CHECK_FALSE(g.open(0.9f, 0.49f, TrackState::Tracking));
  CHECK_FALSE(g.open(0.9f, 0.9f, TrackState::Lost));
  CHECK_FALSE(g.open(0.9f, 0.9f, TrackState::Idle));
}

TEST_CASE("lost after lostAfter low frames in a row, found after foundAfter high ones",
          "[core][gate]") {
  LostDetector d;  // lost below 0.42 for 4 frames; found at 0.58 (or typical - 0.15) for 2
  d.reset();
  TrackState s = TrackState::Tracking;
  for (int i = 0; i < 3; ++i) s = d.step(s, 0.3f);
  REQUIRE(s == TrackState::Tracking);
  s = d.step(s, 0.5f);  // one good frame restarts the count
  for (int i = 0; i < 3; ++i) s = d.step(s, 0.3f);
  REQUIRE(s == TrackState::Tracking);
  s = d.step(s, 0.3f);
  REQUIRE(s == TrackState::Lost);

  s = d.step(s, 0.7f);
  REQUIRE(s == TrackState::Lost);
  s = d.step(s, 0.7f);
  REQUIRE(s == TrackState::Tracking);
  REQUIRE(d.onProbation());
  // On probation, one frame below foundAbove loses it again at once.
  s = d.step(s, 0.5f);
  REQUIRE(s == TrackState::Lost);
  REQUIRE_FALSE(d.onProbation());
  // Found again, probation runs out after probationFrames good frames.
  s = d.step(d.step(s, 0.7f), 0.7f);
  REQUIRE(s == TrackState::Tracking);
  for (int i = 0; i < d.probationFrames; ++i) s = d.step(s, 0.6f);
  REQUIRE(s == TrackState::Tracking);
  REQUIRE_FALSE(d.onProbation());
  s = d.step(s, 0.5f);  // no longer on probation: one middling frame is fine
  REQUIRE(s == TrackState::Tracking);
}

TEST_CASE("lost only when the cues agree: a low frame another cue still sees does not count",
          "[core][gate]") {
  LostDetector d;
  d.reset();
  TrackState s = TrackState::Tracking;
  // The classifier dips for twice lostAfter frames while the filter still sees the target.
  for (int i = 0; i < 2 * d.lostAfter; ++i) s = d.step(s, 0.1f, true);
  REQUIRE(s == TrackState::Tracking);
  // Once the filter no longer sees it either, lostAfter low frames lose it, as before.
  for (int i = 0; i < d.lostAfter - 1; ++i) s = d.step(s, 0.1f, false);
  REQUIRE(s == TrackState::Tracking);
  s = d.step(s, 0.1f, false);
  REQUIRE(s == TrackState::Lost);
  // Neither "found" nor probation listen to it: a low frame while lost stays lost, and
  // one on probation loses the target again.
  s = d.step(d.step(s, 0.1f, true), 0.1f, true);
  REQUIRE(s == TrackState::Lost);
  s = d.step(d.step(s, 0.7f), 0.7f);
  REQUIRE(d.onProbation());
  s = d.step(s, 0.1f, true);
  CHECK(s == TrackState::Lost);
}

TEST_CASE(
    "a look-alike well below the target's usual confidence is not found, from the "
    "first frames on",
    "[core][gate]") {
  for (int tracked : {3, 10, 60}) {
    LostDetector d;
    d.reset();
    TrackState s = TrackState::Tracking;
    for (int i = 0; i < tracked; ++i) s = d.step(s, 0.8f);
    INFO("tracked " << tracked << " frames at 0.8, found threshold " << d.foundThreshold());
    // The usual confidence less the margin, whether the track is 3 frames old or 60.
    CHECK(d.foundThreshold() == Approx(0.65f).margin(1e-4));
    for (int i = 0; i < d.lostAfter; ++i) s = d.step(s, 0.2f);
    REQUIRE(s == TrackState::Lost);
    for (int i = 0; i < 10; ++i) s = d.step(s, 0.62f);  // the look-alike
    CHECK(s == TrackState::Lost);
    s = d.step(d.step(s, 0.7f), 0.7f);  // the target
    CHECK(s == TrackState::Tracking);
  }
  // Low-confidence tracking (a hard target): the floor foundAbove holds.
  LostDetector d;
  d.reset();
  TrackState s = TrackState::Tracking;
  for (int i = 0; i < 30; ++i) s = d.step(s, 0.6f);
  CHECK(d.foundThreshold() == Approx(d.foundAbove));
}

TEST_CASE("probation lasts exactly the tuned number of frames after the target is found",
          "[core][gate]") {
  // Counted frame by frame, not with the detector's own member: a probation one frame
  // shorter or longer than tuning::lost::kProbationFrames fails here.
  LostDetector d;
  d.reset();
  TrackState s = TrackState::Tracking;
  for (int i = 0; i < d.lostAfter; ++i) s = d.step(s, 0.2f);
  REQUIRE(s == TrackState::Lost);
  for (int i = 0; i < d.foundAfter; ++i) s = d.step(s, 0.7f);
  REQUIRE(s == TrackState::Tracking);
  int probationFrames = 0;
  while (d.onProbation() && probationFrames < 100) {
    s = d.step(s, 0.7f);
    ++probationFrames;
  }
  CHECK(probationFrames == tuning::lost::kProbationFrames);

  // The last of those frames is still judged on probation: a middling one (between
  // lostBelow and foundAbove) there loses the target again.
  d.reset();
  s = TrackState::Tracking;
  for (int i = 0; i < d.lostAfter; ++i) s = d.step(s, 0.2f);
  for (int i = 0; i < d.foundAfter; ++i) s = d.step(s, 0.7f);
  REQUIRE(s == TrackState::Tracking);
  for (int i = 0; i < tuning::lost::kProbationFrames - 1; ++i) s = d.step(s, 0.7f);
  REQUIRE(d.onProbation());
  s = d.step(s, 0.5f);
  CHECK(s == TrackState::Lost);
}
