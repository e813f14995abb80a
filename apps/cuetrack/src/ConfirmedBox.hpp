// What every output (stdout, CSV, the serial link, the window) carries while the target is
// lost: the last box the tracker confirmed, with the lost state. The tracker's own box in a
// lost frame is wherever its search looks (a corner, partly off the image); a consumer that
// read the box without the state would steer at it (issue 43).
#pragma once

#include <cstdint>

#include "cuetrack_proto.h"

namespace cuetrack::app {

class ConfirmedBox {
 public:
  // Remembers a confirmed frame (tracking, not occluded: the target was seen there); in a
  // lost or searching frame puts the last confirmed box and centre in its place.
  void apply(ctp_track_t& msg) {
    if (msg.state == CTP_STATE_IDLE) {
      _has = false;
      return;
    }
    if (msg.state == CTP_STATE_TRACKING) {
      if ((msg.flags & CTP_FLAG_OCCLUDED) != 0) return;  // where it went behind: not seen
      _has = true;
      for (int i = 0; i < 4; ++i) _boxPx[i] = msg.box_px[i];
      for (int i = 0; i < 3; ++i) _centreMm[i] = msg.centre_mm[i];
      _has3d = (msg.flags & CTP_FLAG_HAS_3D) != 0;
      return;
    }
    // Lost or searching: the box (and centre) last confirmed; without one, none at all.
    for (int i = 0; i < 4; ++i) msg.box_px[i] = _has ? _boxPx[i] : int16_t{0};
    for (int i = 0; i < 3; ++i) msg.centre_mm[i] = _has ? _centreMm[i] : 0;
    const uint8_t measured = CTP_FLAG_HAS_3D | CTP_FLAG_OCCLUDED | CTP_FLAG_DEPTH_PREDICTED;
    msg.flags =
        static_cast<uint8_t>((msg.flags & ~measured) | (_has && _has3d ? CTP_FLAG_HAS_3D : 0u));
  }
  void clear() { _has = false; }

 private:
  bool _has = false;
  bool _has3d = false;
  int16_t _boxPx[4] = {};
  int32_t _centreMm[3] = {};
};

}  // namespace cuetrack::app
