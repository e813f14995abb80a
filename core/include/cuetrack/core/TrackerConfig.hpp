// Run-time switches of the tracker, and the named configurations of the paper's
// tests (1.1-1.4 RGB, 2.1-2.5 RGB-D) plus `best`. Capacities are in Config.hpp.
#pragma once

#include <cstdint>

#include "cuetrack/core/Config.hpp"

namespace cuetrack {

enum class StateSpace : uint8_t { Image2d, Cylinder3d };
enum class FeatureSampling : uint8_t {
  Dense,
  Sparse
};  // Dense: Klein's old pool; Sparse: the paper's
enum class Estimator : uint8_t {
  MaxWeight,     // the particle with the highest weight (the paper)
  WeightedMean,  // the weighted mean of all particles
};

inline constexpr int kMaxTemplateScaleSteps = 4;
inline constexpr int kMaxSearchRefineWindows = 16;

struct TrackerConfig {
  // Paper parameters
  int numParticles = 2000;        // <= kMaxParticles
  int numWeakClassifiers = 32;    // M, <= kMaxWeakClassifiers
  int numTrainingExamples = 140;  // <= kMaxTrainingExamples
  StateSpace stateSpace = StateSpace::Image2d;
  bool useGray = true;    // grayscale gradient features
  bool useColour = true;  // colour average features
  bool useDepth = false;  // depth gradient features
  FeatureSampling sampling = FeatureSampling::Sparse;
  bool dynamicPool = true;              // pool update (tests x.1); off in x.2
  float velocityNoiseMm2PerS2 = 550.f;  // AR(1) velocity noise variance, 3D [mm^2/s^2]

  // Beyond the paper (off in the paper's presets, on in `best`)
  bool adaptCylinderSize = false;  // D, H (and centre) follow the silhouette measured in depth
  bool lostDetection = false;      // declare lost, freeze learning, re-acquire
  bool fallbackTo2d = false;       // 3D/depth requested but the frame has none: run 2D RGB
  bool scaleAnchor2d = false;      // 2D: size and centre follow the init template's best match
  bool anchorMovesCloud = false;   // scaleAnchor2d: the particles follow part of its correction
  bool modeGuard = false;     // a split cloud: estimate from the best particle's mode, not the mean
  bool refineSearch = false;  // lostDetection: the best fresh search windows climb to a peak
  // Fast targets and slow or dropped frames. After a learnt frame every jumpEvery-th
  // particle jumps (MotionModel2d/3d::jump): in 2D always, and a particle coasts on its
  // velocity over dropped frames; in 3D only when frames come further apart than
  // jumpMinDtS, and a jump that the depth correction puts on another surface is undone.
  bool fastMotion = false;
  // fallbackTo2d: when a 3D/depth configuration runs 2D RGB, these replace the 3D values
  // (0 = same as in 3D): the RGB-only classifier needs more weak classifiers (the paper's
  // RGB tests use 32), and partial occlusions in RGB dip the confidence for longer.
  int numWeakClassifiers2d = 0;  // M in the 2D fallback, <= kMaxWeakClassifiers
  int lostAfter2d = 0;           // lost detection in the 2D fallback: frames of low confidence
  // lostDetection, 3D: no learning from an estimate whose depth lies more than this part
  // off the confirmed depth, either way; 0 = no such check. The confirmed depth is the
  // last learnt or re-found one, and it follows the estimate while that moves smoothly
  // (by at most learnDepthFollow a frame at 30 fps). A cloud sliding onto the wall behind
  // a low-contrast target can score well for a frame, and one positive learnt there
  // teaches the wall (docs/algorithm.md).
  float learnMaxDepthChange = 0.12f;
  float learnDepthFollow = 0.03f;

  // Implementation parameters (docs/algorithm.md), the same in every preset
  Estimator estimator = Estimator::WeightedMean;
  float weightGain = 12.f;          // lambda: particle weight = exp(lambda * c), c in [-1, 1]
  float learnConfidence = 0.55f;    // update gate: confidence (c + 1) / 2 at the estimate >= this
  float learnConcentration = 0.5f;  // ... and weighted mean overlap of particles with it >= this
  int negativesPerUpdate = 10;      // negatives added per learning step
  int initialPositives = 9;         // the init box plus slightly shifted copies, kept for good
  float initialJitter = 0.03f;      // ... shifted and rescaled by N(0, this^2) of the side
  // 2D, where the classifier alone places the window to the pixel: more, closer copies
  int initialPositives2d = 17;
  float initialJitter2d = 0.015f;
  float anchorWeight = 2.f;          // boosting weight of a kept initial positive vs a recent one
  int boostCandidates = 48;          // GentleBoost rounds after the first search these best
  int boostRefreshRounds = 12;       // ... and every this many rounds the whole pool again
  float nearNegativeOverlap = 0.5f;  // near-miss negatives overlap the estimate less than this
  float shrunkNegativeScale =
      0.65f;  // > 0: some near negatives: the estimate scaled by this or 1/this
  // 2D (where the classifier alone sets the window's size): a shrunk or grown near negative
  // is anchored at the estimate's start, centre or end along each axis; else centred.
  bool anchoredNegatives2d = true;
  float shiftedNegativeFraction =
      0.2f;                          // > 0: some near negatives are the estimate shifted by this
  float positionNoise2d = 0.09f;     // 2D motion noise per frame, x sqrt(w h)
  float scaleNoise2d = 0.015f;       // 2D std of ln(scale) per frame
  float aspectNoise2d = 0.004f;      // 2D: ln w += a, ln h -= a, a ~ N(0, this²) per frame
  int jumpEvery = 10;                // fastMotion: one particle in this many jumps ...
  float jumpScale = 3.f;             // ... by this many times the position noise
  float jumpMinDtS = 0.045f;         // ... in 3D only with frames further apart (30 fps: none)
  float jumpMaxDepthChange = 0.15f;  // ... and undone if its depth moved more (a part of z)
  float cylinderSizeNoise = 0.002f;  // adaptCylinderSize: std of ln D and ln H per frame
  float cylinderSizeGain = 0.1f;     // ... per learnt frame, ln D, ln H move this part of the
                                     // way to the silhouette measured in depth (0: walk only)
  float cylinderCentreGain = 0.2f;   // ... and the window's centre this part to the silhouette's
  float sizeGain = 0.3f;             // 2D: alpha-beta filter on ln w, ln h: alpha
  float sizeRateGain = 0.05f;        // ... beta (the rate: steady zooms are followed without lag)
  // 2D scale anchor (scaleAnchor2d): the classifier peaks at whatever size it learnt last, so the
  // size random-walks. Each frame the init box's grey template is matched (NCC) on a (2K+1)^2
  // ladder of widths x heights around the estimate; if the best match is good (the target still
  // looks as it did), the size moves templateGain of the way there.
  int templateScaleSteps = 2;       // K, <= kMaxTemplateScaleSteps
  float templateScaleStep = 0.04f;  // ladder step of ln w, ln h
  float templateMinNcc = 0.85f;     // best match needed
  float templateGain = 0.3f;        // fraction of the ladder's correction applied
  // ... then the best size's template is matched at -2..2 shifts of templateShiftStep of
  // its side along each axis; a good best match (>= templateMinNcc) moves the centre
  // templateShiftGain of the way (0 step: size only).
  float templateShiftStep = 0.02f;
  float templateShiftGain = 0.6f;
  // anchorMovesCloud: on a frame whose estimate is confident enough to learn from
  // (learnConfidence), every particle is rescaled and shifted by this part of the
  // anchor's correction, so the correction stays in the state instead of being applied
  // afresh to each frame's classifier-only mean (docs/algorithm.md).
  float templateCloudGain = 0.5f;
  // modeGuard (WeightedMean only): when the weighted mean's own score is this far below the
  // best particle's, and that particle's confidence (c + 1) / 2 is at least the minimum, the
  // cloud has split over two places and the mean lies between them; the estimate is then
  // the weighted mean of the particles whose windows overlap the best particle's by >= 0.5.
  float modeGuardMargin = 0.2f;
  float modeGuardMinConfidence = 0.7f;
  // refineSearch: while lost, this many of the frame's fresh search windows, the best
  // scored, are hill-climbed in image position before weighing (<= kMaxSearchRefineWindows).
  int searchRefineWindows = 8;
};

enum class Preset : uint8_t {
  Test1_1,
  Test1_2,
  Test1_3,
  Test1_4,  // RGB, 2D state (BoBoT, PROST)
  Test2_1,
  Test2_2,
  Test2_3,
  Test2_4,
  Test2_5,  // RGB-D (BoBoT-D)
  Best,
};
inline constexpr int kNumPresets = 10;

TrackerConfig presetConfig(Preset preset);
// "1.1" ... "2.5", "best"; returns false for an unknown name.
bool parsePreset(const char* name, Preset* out);
const char* presetName(Preset preset);

}  // namespace cuetrack
