// Turns inbound protocol frames into requests on the app (AppControl) and the
// immediate reply: ACK, ERROR, or none yet (START is answered after the tracker has
// tried the box on the next frame).
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::app {

class AppControl {
 public:
  virtual ~AppControl() = default;
  virtual void requestStart(const Box& boxPx, uint16_t cmdId) = 0;
  virtual void requestReset() = 0;
  virtual void requestStop() = 0;
  virtual void setRateHz(uint16_t hz) = 0;
};

struct Reply {
  enum class Kind : uint8_t { None, Ack, Error };
  Kind kind = Kind::None;
  uint8_t cmdType = 0;
  uint16_t cmdId = 0;
  uint8_t code = 0;  // CTP_E_* for Error
};

class CommandHandler {
 public:
  // decodeError: CTP_OK for a frame that passed CRC, else the decoder's error.
  Reply handle(int decodeError, const ctp_frame_t& frame, AppControl& app);
  uint32_t accepted() const { return _accepted; }
  uint32_t rejected() const { return _rejected; }

 private:
  uint32_t _accepted{0};
  uint32_t _rejected{0};
};

}  // namespace cuetrack::app
