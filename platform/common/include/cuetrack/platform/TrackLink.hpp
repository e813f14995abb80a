// The serial-side protocol behind one small interface, so the pipeline does not care
// whether it speaks cuetrack's own protocol (apps/cuetrack SerialLink) or MAVLink
// (platform/mavlink MavlinkLink). A link reads commands and applies them through
// LinkControl, sends one report per frame, heartbeats, and answers a start once the
// tracker has tried the box.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::platform {

// A request to start tracking, resolved into a pixel box on the next frame (where the
// image size and depth are known).
struct StartRequest {
  enum class Kind : uint8_t { BoxPx, BoxNormalised, PointNormalised };
  Kind kind = Kind::BoxPx;
  Box box{};           // BoxPx: [px]; BoxNormalised: x, y, w, h as fractions of the image
  float pointX = 0.f;  // PointNormalised: the point, fractions of width and height
  float pointY = 0.f;
  float radius = 0.f;  // PointNormalised: fraction of the image width, 0 = not given
  uint32_t token = 0;  // the link's own handle, given back in answerStart()
};

enum class StartOutcome : uint8_t {
  Started,     // the tracker took the box
  Refused,     // the tracker refused it (outside the image, too small)
  Superseded,  // a newer start, a reset or a stop came first, or the run ended
};

// What a link's commands may ask of the app.
class LinkControl {
 public:
  virtual ~LinkControl() = default;
  virtual void requestStart(const StartRequest& request) = 0;  // answered by answerStart()
  virtual void requestReset() = 0;                             // back to idle
  virtual void requestStop() = 0;                              // end the run
};

// The app's state as heartbeats tell it.
struct LinkStatus {
  uint8_t state = CTP_STATE_IDLE;  // CTP_STATE_*
  uint32_t frames = 0;
  bool noCamera = false;  // waiting for a camera to be plugged in
};

// One frame's result for the link: the quantised track every output shares, and what
// a link needs to put it in other units (normalised box, angles).
struct FrameReport {
  ctp_track_t track{};
  int widthPx = 0, heightPx = 0;
  CameraIntrinsics intrinsics{};
};

struct LinkStats {
  // Every message is in one of three: sent + txDropped + queued = all sent so far.
  uint32_t sent = 0;       // messages written whole to the line
  uint32_t queued = 0;     // messages waiting in the queue (at exit: never sent, dropped)
  uint32_t txDropped = 0;  // messages dropped: line too slow, or disconnected
  uint32_t rxFrames = 0;   // good inbound frames
  uint32_t rxErrors = 0;   // rejected inbound frames (framing, CRC, malformed commands),
                           // and datagrams the OS dropped before they were read
  // Of rxErrors, MAVLink's discarded bytes by reason, one per run (docs/mavlink.md).
  uint32_t rxBadCrc = 0, rxBadLength = 0, rxBadUnknown = 0;
  uint32_t rxRefused = 0;  // well-formed commands refused: not from an accepted sender
  uint32_t disconnects = 0;
  uint32_t reconnects = 0;
};

class TrackLink {
 public:
  virtual ~TrackLink() = default;
  // Never waits: reads and applies commands, flushes the queue, reconnects, heartbeats.
  virtual void poll(LinkControl& control, const LinkStatus& status) = 0;
  // One report per frame (a link may thin them to its configured rate).
  virtual void sendFrame(const FrameReport& report) = 0;
  // The one reply to a start request.
  virtual void answerStart(uint32_t token, StartOutcome outcome) = 0;
  // At exit: waits (at most ~maxMs) until queued bytes are on the line.
  virtual bool drain(int maxMs) = 0;
  virtual bool connected() const = 0;
  virtual const LinkStats& stats() const = 0;
};

}  // namespace cuetrack::platform
