// What one tracker step returns. A plain value: copied into messages by apps/.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack {

enum class TrackState : uint8_t {
  Idle = 0,      // no target yet (before init, or after reset)
  Tracking = 1,  // target located
  Lost = 2,      // target judged lost; model frozen, searching to re-acquire
};

// Per-stage wall time of one update [us]; all zero when the tracker has no Clock.
struct StageTimesUs {
  uint32_t predict = 0;   // motion model (and the lost search's draws) + 3D depth correction
  uint32_t features = 0;  // colour conversion + integral images of the particles' region
  uint32_t weigh = 0;     // classifier on every particle (and the lost search's climb), estimate
  uint32_t learn = 0;     // lost detection, update gate, training-set and pool update, re-training
  uint32_t total = 0;     // all of update(), resampling included
};

struct TrackResult {
  TrackState state = TrackState::Idle;
  Box box{};                   // estimate [px]
  bool hasPosition3d = false;  // 3D state space only
  float positionMm[3] = {
      0, 0, 0};  // cylinder centre in camera coordinates [mm] (x right, y down, z forward)
  float confidence = 0.f;  // strong classifier output at the estimate, in [0, 1]
  bool learned = false;    // the update gate opened this frame
  // 3D (occlusionGate): the target is hidden behind a nearer surface; state is Tracking,
  // box and positionMm are where it was last seen, and the search for it goes on.
  bool occluded = false;
  // 3D: the target's box has too little valid depth (tuning::kMinDepthSupport): positionMm's
  // depth is predicted from its motion, not measured, and colour alone placed the box.
  bool depthPredicted = false;
  StageTimesUs timesUs{};
};

}  // namespace cuetrack
