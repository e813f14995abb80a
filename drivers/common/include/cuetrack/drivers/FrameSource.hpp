// One interface for every source of frames: recordings (BoBoT video, RGB-D folder,
// OTB folder, fakenect), synthetic scenes and the live Kinect. The tracker cannot
// tell them apart. Frames land in caller-owned fixed buffers (FrameSlot), so a
// source needs no per-frame allocation of its own.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Frame.hpp"
#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Image.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/drivers/FrameScale.hpp"

namespace cuetrack {

// Caller-owned storage for one frame (about 1.5 MiB: keep it static or allocate once).
struct FrameSlot {
  FixedImage<Rgb8, kMaxImageWidth, kMaxImageHeight> rgb;
  FixedImage<uint16_t, kMaxImageWidth, kMaxImageHeight> depthMm;  // [mm], 0 = none
  bool hasDepth = false;
  uint64_t timeUs = 0;            // capture time [us]
  CameraIntrinsics intrinsics{};  // of rgb (source's own, or Kinect v1 defaults)
  int index = 0;                  // 0-based frame number within the source
  bool hasGroundTruth = false;    // the source has a ground-truth line for this frame
  Box groundTruth{};              // [px]; empty() = target not visible
  // The target's true centre in camera coordinates [mm] (x right, y down, z forward), from
  // sources that know it exactly (synthetic scenes); scores TrackResult::positionMm.
  bool hasTruthMm = false;
  float truthCentreMm[3] = {0.f, 0.f, 0.f};
  // How the source's own frame was scaled into rgb (FrameScale.hpp); not scaled by default.
  FrameScale scale{};

  // Views for the tracker.
  Frame frame() const {
    Frame f;
    f.rgb = rgb.view();
    if (hasDepth) f.depthMm = depthMm.view();
    f.timeUs = timeUs;
    f.intrinsics = intrinsics;
    return f;
  }
};

enum class ReadStatus : uint8_t {
  Ok,     // slot filled
  End,    // no more frames (end of recording, or stream stopped cleanly)
  Error,  // see error(): one line naming the file (and line) or device at fault
};

class FrameSource {
 public:
  virtual ~FrameSource() = default;
  virtual ReadStatus next(FrameSlot& out) = 0;
  // Last error as one line, e.g. "seq/depth/000012.png: truncated PNG". Valid until the next call.
  virtual const char* error() const = 0;
  // Short name for logs and result files (file or folder name without extension).
  virtual const char* name() const = 0;
  // Frames in the source if known, else -1.
  virtual int frameCount() const { return -1; }
  // The source's frame rate [frames/s] (a writer's container rate), 0 if unknown.
  virtual double nominalFps() const { return 0.0; }
  // Frames skipped as unreadable so far (with the skip-bad-frames option).
  virtual int skippedFrames() const { return 0; }
  // A problem that did not stop the source (ground truth left out), "" when none.
  virtual const char* warning() const { return ""; }
  // True while no frame can come because the device is not there yet (a source that
  // waits for its camera to be plugged in); callers may tell their peers so.
  virtual bool awaitingDevice() const { return false; }

  // A source that can wait long for a frame (the live Kinect: up to its stall timeout)
  // calls `hook(ctx)` about every kIdleSliceMs while it waits, on the thread that called
  // next(), so the caller keeps its serial link alive (heartbeats, commands) through a
  // stall. A hook that returns true ends the wait: next() returns End. Sources that
  // never wait (files, synthetic scenes) never call it.
  using IdleHook = bool (*)(void* ctx);
  static constexpr unsigned kIdleSliceMs = 100;
  void setIdleHook(IdleHook hook, void* ctx) {
    _idleHook = hook;
    _idleCtx = ctx;
  }

 protected:
  // True when the hook asks to stop waiting.
  bool idle() { return _idleHook != nullptr && _idleHook(_idleCtx); }
  // A source that wraps another hands its caller's hook on to it.
  void passIdleHookTo(FrameSource& inner) const { inner.setIdleHook(_idleHook, _idleCtx); }

 private:
  IdleHook _idleHook = nullptr;
  void* _idleCtx = nullptr;
};

}  // namespace cuetrack
