// Run-time switches of the tracker, and the named configurations of the paper's
// tests (1.1-1.4 RGB, 2.1-2.5 RGB-D) plus `best`. Capacities are in Config.hpp.
#pragma once

#include <cstdint>

#include "cuetrack/core/config/Config.hpp"

namespace cuetrack {

enum class StateSpace : uint8_t { Image2d, Cylinder3d };
enum class FeatureSampling : uint8_t {
  Dense,
  Sparse
};  // Dense: Klein's old pool; Sparse: the paper's

// What a preset or a user changes: the paper's parameters and the beyond-the-paper
// switches. Every other number is a named constant in Tuning.hpp.
struct TrackerConfig {
  // The paper's parameters
  int numParticles = 2000;      // <= kMaxParticles
  int numWeakClassifiers = 32;  // M, <= kMaxWeakClassifiers
  StateSpace stateSpace = StateSpace::Image2d;
  bool useGray = true;    // grayscale gradient features
  bool useColour = true;  // colour average features
  bool useDepth = false;  // depth gradient features
  FeatureSampling sampling = FeatureSampling::Sparse;
  bool dynamicPool = true;  // pool update (tests x.1); off in x.2

  // Beyond the paper: on in `best`; each can be turned off in cuetrack-bench as an
  // ablation (`best-nolost`, ...; apps/bench/CuetrackAdapter.cpp).
  bool adaptCylinderSize = false;  // D, H (and centre) follow the silhouette measured in depth
  bool lostDetection = false;      // declare lost, freeze learning, re-acquire
  bool fallbackTo2d = false;       // 3D/depth requested but the frame has none: run 2D RGB
  // Fast targets and slow or dropped frames: after a learnt frame some particles jump
  // (FastMotion); in 2D a particle coasts on its velocity over dropped frames.
  bool fastMotion = false;
  // Abrupt motion: a slowly learnt gray template is matched densely around the last
  // estimate (CorrelationCue); particles are drawn at its peak and weighed by it too.
  bool correlationCue = false;
  // ... the cue is a correlation filter on HOG, gray and colour cells (CorrelationFilter)
  // instead of the gray template; searched at three scales in 2D, at the cylinder's own
  // in 3D (the depth sets the scale).
  bool correlationFilter = false;
  // 3D: a frame whose box is mostly covered by a nearer surface is not learnt (Occlusion).
  bool occlusionGate = false;
  // 2D negatives shrunk or grown around the estimate are anchored at its start, centre or
  // end along each axis (else centred): an implementation choice of every preset, here so
  // that its effect can be measured (`1.1-centrednegatives`).
  bool anchoredNegatives2d = true;
  // fallbackTo2d: when a 3D/depth configuration runs 2D RGB, these replace the 3D values
  // (0 = same as in 3D): the RGB-only classifier needs more weak classifiers (the paper's
  // RGB tests use 32), and partial occlusions in RGB dip the confidence for longer.
  int numWeakClassifiers2d = 0;  // M in the 2D fallback, <= kMaxWeakClassifiers
  int lostAfter2d = 0;           // lost detection in the 2D fallback: frames of low confidence
  // A track that runs 2D (asked for, or the fallback) follows the background-aware
  // correlation filter (FilterTracker): its box is the filter's, which beats the
  // particles on real video (docs/algorithm.md). With lostDetection the classifier
  // judges it (lost, found again by the particle search); without, the filter is alone
  // (the `dcf` configuration). `best` without depth.
  bool filterLeads2d = false;
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
  Dcf,      // the background-aware correlation filter alone (issue 53)
  Best,     // last: the tests take the presets before it as the paper's and dcf
};
inline constexpr int kNumPresets = 11;

TrackerConfig presetConfig(Preset preset);
// "1.1" ... "2.5", "dcf", "best"; returns false for an unknown name.
bool parsePreset(const char* name, Preset* out);
const char* presetName(Preset preset);

}  // namespace cuetrack
