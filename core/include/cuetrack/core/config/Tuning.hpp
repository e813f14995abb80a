// Every number of the tracker that no preset changes, written once, grouped by the
// component that uses it, each with its unit and why. What a preset or a user does
// change is in TrackerConfig.hpp; capacities (array sizes) are in Config.hpp.
// docs/algorithm.md explains each choice; docs/experiments.md what else was tried.
#pragma once

namespace cuetrack::tuning {

// Particle weights: w = exp(kWeightGain * (c - c_max)), c in [-1, 1] the classifier's
// score. 12 keeps ~50 effective particles of 2000 on a sharp peak.
inline constexpr float kWeightGain = 12.f;

// The update gate (the paper's): learn when the confidence (c + 1) / 2 at the estimate
// is at least this ...
inline constexpr float kLearnConfidence = 0.55f;
// ... and the particles' weighted mean overlap with the estimate at least this.
inline constexpr float kLearnConcentration = 0.5f;

namespace training {
inline constexpr int kExamples = 140;  // the paper's training set size, <= kMaxTrainingExamples
inline constexpr int kNegativesPerUpdate = 10;  // negatives added per learning step
// The init box plus slightly shifted and rescaled copies (by N(0, jitter^2) of the side),
// kept for good. 2D needs more, closer copies: the classifier alone places its window.
inline constexpr int kInitialPositives3d = 9;
inline constexpr float kInitialJitter3d = 0.03f;
inline constexpr int kInitialPositives2d = 17;
inline constexpr float kInitialJitter2d = 0.015f;
inline constexpr float kAnchorWeight = 2.f;     // boosting weight of a kept initial positive
inline constexpr int kBoostCandidates = 48;     // GentleBoost rounds after the first search these
inline constexpr int kBoostRefreshRounds = 12;  // ... and every this many rounds all again
}  // namespace training

namespace negatives {
inline constexpr float kNearOverlap = 0.5f;   // near-miss negatives overlap the estimate less
inline constexpr float kShrunkScale = 0.65f;  // some near negatives: the estimate x this or 1/this
inline constexpr float kShiftedFraction = 0.2f;  // some: the estimate shifted by this of its side
}  // namespace negatives

namespace motion2d {
// Noise std per frame, as fractions of the window's mean side sqrt(w h).
inline constexpr float kPositionNoise = 0.09f;
inline constexpr float kVelocityNoise = 0.02f;
inline constexpr float kVelocityDecay = 0.9f;  // du' = decay du + noise: velocities stay bounded
inline constexpr float kScaleNoise = 0.015f;   // std of ln(scale) per frame
inline constexpr float kAspectNoise = 0.004f;  // ln w += a, ln h -= a, a ~ N(0, this^2)
}  // namespace motion2d

namespace motion3d {
// The paper's AR(1) velocity noise variance accrued per second [mm^2/s^2 per s].
inline constexpr float kVelocityNoiseMm2PerS2 = 550.f;
// Position diffusion, x D per sqrt(frame of 1/30 s): the paper's velocity noise alone
// moves a particle by under a millimetre a frame.
inline constexpr float kPositionNoise = 0.12f;
}  // namespace motion3d

// A target narrower or lower than this [px] is tracked on a window padded with context
// to this side (WindowPadding): on the 32-cell feature grid a smaller window rounds most
// features' halves to nothing.
inline constexpr float kMinTrackedSidePx = 16.f;

// While lost, the motion noise is this many times larger, so the cloud spreads.
inline constexpr float kLostSpread = 3.f;
// The ROI of the integral tables: the particles' boxes plus this x their mean size per side.
inline constexpr float kRoiMarginSides = 1.6f;

namespace fastMotion {
inline constexpr int kJumpEvery = 10;     // one particle in this many jumps ...
inline constexpr float kJumpScale = 3.f;  // ... by this many times the position noise
// 3D: only with frames further apart than this [s] (at 30 fps the AR(1) model keeps up) ...
inline constexpr float kJumpMinDtS = 0.045f;
// ... and a jump whose depth moved by more than this part of z is undone (it landed on
// another surface: a twin further back, the background).
inline constexpr float kJumpMaxDepthChange = 0.15f;
}  // namespace fastMotion

namespace cylinder {                         // adaptCylinderSize
inline constexpr float kSizeNoise = 0.002f;  // std of ln D and ln H per frame
inline constexpr float kSizeGain = 0.1f;     // per learnt frame, ln D, ln H move this part
                                             // of the way to the silhouette in depth
inline constexpr float kCentreGain = 0.2f;   // ... and the window's centre this part
}  // namespace cylinder

namespace size2d {                         // the alpha-beta filter on the 2D estimate's ln w, ln h
inline constexpr float kGain = 0.3f;       // alpha
inline constexpr float kRateGain = 0.05f;  // beta: steady zooms followed without lag
}  // namespace size2d

namespace lost {                             // LostDetector
inline constexpr float kLostBelow = 0.42f;   // confidence under which a frame is a miss
inline constexpr int kLostAfter = 4;         // misses in a row that make the target lost
inline constexpr float kFoundAbove = 0.58f;  // confidence of a hit while lost
inline constexpr int kFoundAfter = 2;        // hits in a row that find it again
inline constexpr int kProbationFrames = 8;   // then one frame under kFoundAbove loses it again
// Found needs the typical tracked confidence less this (a look-alike scores lower).
inline constexpr float kFoundMargin = 0.15f;
inline constexpr float kTypicalRate = 0.1f;  // weight of the latest frame in that running mean
// PeakContrast: an estimate scoring less than this [score units, c in -1..1] above the
// windows one side away does not stand out from its surroundings: a miss. A tracked
// target stands out by about 1 (less on real video, more on the synthetic scenes); a box
// on a plain wall by nothing.
inline constexpr float kMinContrast = 0.1f;
// The correlation filter's peak box "on the estimate" (LostDetector's stillSeen): the
// usual overlap for "the same place". Set before measuring, not tuned.
inline constexpr float kOnEstimate = 0.5f;
// filterLeads2d: the leading filter still sees the target while its peak to sidelobe
// ratio reaches this (tracked real videos: 5th percentile 3.5-9.4; an untextured box
// about 3), whatever its peak's height.
inline constexpr float kLeadSharpness = 5.f;
}  // namespace lost

namespace search {  // re-acquisition while lost
// Every kSearchEvery-th particle is drawn anew each frame: half anywhere in the image,
// half around the last learnt estimate within a radius of (0.5 + kGrowth x frames lost)
// window sides.
inline constexpr int kEvery = 2;
inline constexpr float kGrowth = 0.25f;
inline constexpr float kScaleNoise2d = 0.15f;  // 2D: std of ln(scale) of a fresh window
inline constexpr float kInside = 0.8f;         // a window must lie this much inside the image
}  // namespace search

namespace correlation {  // CorrelationCue (correlationCue)
// Particle weights: w = exp(kWeightGain (c - c_max) + kResponseGain (r - r_max)), r in
// [-1, 1] the template's NCC at the particle's centre. 3, 6 and 12 gave about the same
// (docs/experiments.md): the cue matters, its gain hardly.
inline constexpr float kResponseGain = 3.f;
// One particle in kEvery is drawn at the map's peak when the peak reaches kMinPeak (at 0.5
// a weak peak on a small, turning target pulled the cloud off it; docs/experiments.md).
inline constexpr float kMinPeak = 0.7f;
inline constexpr int kEvery = 20;
inline constexpr int kSlot = 3;  // ... i % kEvery == kSlot (FastMotion's jumpers are 1, 11, ...)
// The template follows the target's appearance on learnt frames at this rate (0.05 and 0.2
// did no better; docs/experiments.md).
inline constexpr float kLearnRate = 0.1f;
// While lost, this many tiles of the image (each 3 x 3 sides of the last learnt window,
// one search() each) are searched a frame: a 640x480 image in 2-10 frames.
inline constexpr int kScanTilesPerFrame = 3;
}  // namespace correlation

namespace dcf {  // CorrelationFilter (correlationCue with correlationFilter)
// Ridge regularisation of the filter: keeps frequencies the features hardly hold from
// being amplified (DSST's and KCF's value for features of this range).
inline constexpr float kLambda = 1e-2f;
// The label's spread: kLabelSigma times the target's side in cells (KCF's 0.1).
inline constexpr float kLabelSigma = 0.1f;
// Scales searched: the window over kScaleStep, and times it; a scale other than the
// current one must beat it by 1 / kScalePenalty (a change of size needs evidence).
inline constexpr float kScaleStep = 1.04f;
inline constexpr float kScalePenalty = 0.98f;
// Particles are drawn at the filter's peak whatever its height (the classifier judges
// them): the peak of a target blurred by a jump is low (0.15 against 0.5-0.6 on Jumping)
// yet in the right place. A minimum of 0.3 or 0.1 did worse (docs/experiments.md).
inline constexpr float kMinPeak = 0.f;
// The filter learns at this rate on every tracked frame (not only on learnt ones).
inline constexpr float kLearnRate = 0.05f;
}  // namespace dcf

namespace depthGuard {  // 3D, lostDetection
// The estimate's depth over the last confirmed one (or its inverse) below this: the cloud
// has jumped onto something in front or behind; a miss, and not learnt.
inline constexpr float kJumpRatio = 0.75f;
// Found again nearer than 1 / kFoundRatio or farther than kFoundRatio times the confirmed
// depth: the search has found the floor or a wall behind (issue 30's leave-return and the
// real-still occlusion found textures at twice the depth), or the look-alike in front
// (lookalike: at 1.6 m against 2.4 m), not the target. The jump guard's ratio (1.5 did a
// little worse; docs/experiments.md).
inline constexpr float kFoundRatio = 1.f / kJumpRatio;
}  // namespace depthGuard

namespace occlusion {  // 3D, Occlusion: a frame whose box is covered is not learnt
// A surface more than D/2 plus this (kGapRatio x the depth, at least kMinGapMm) in front
// of the target's front surface is an occluder: past the target's own relief and Kinect
// depth noise (~1.5% at 2 m).
inline constexpr float kMinGapMm = 60.f;
inline constexpr float kGapRatio = 0.03f;
// Covered: more than this fraction of the box's valid depth is an occluder.
inline constexpr float kCoveredAbove = 0.25f;
// Lost while covered, the target is reported where it was last learnt for at most this.
inline constexpr float kMaxHoldS = 2.f;
}  // namespace occlusion

// 3D: under this fraction of valid depth pixels in the inner half of the target's box
// (a black, glossy or sunlit surface; nearer than the Kinect's 0.5 m), its depth is not
// measured: the particles keep their predicted depth (correctDepth finds no surface) and
// colour alone places the box. TrackResult::depthPredicted says so.
inline constexpr float kMinDepthSupport = 0.25f;

}  // namespace cuetrack::tuning
