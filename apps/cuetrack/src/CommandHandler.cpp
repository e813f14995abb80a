#include "CommandHandler.hpp"

namespace cuetrack::app {

Reply CommandHandler::handle(int decodeError, const ctp_frame_t& frame, AppControl& app) {
  Reply r;
  if (decodeError != CTP_OK) {
    ++_rejected;
    r.kind = Reply::Kind::Error;
    r.code = static_cast<uint8_t>(decodeError);
    return r;
  }
  ctp_command_t c;
  const int err = ctp_parse_command(&frame, &c);
  r.cmdType = c.type != 0 ? c.type : frame.type;
  r.cmdId = c.id;
  if (err != CTP_OK) {
    ++_rejected;
    r.kind = Reply::Kind::Error;
    r.code = static_cast<uint8_t>(err);
    return r;
  }
  ++_accepted;
  r.kind = Reply::Kind::Ack;
  switch (c.type) {
    case CTP_CMD_START:
      app.requestStart(Box{static_cast<float>(c.box_px[0]), static_cast<float>(c.box_px[1]),
                           static_cast<float>(c.box_px[2]), static_cast<float>(c.box_px[3])},
                       c.id);
      r.kind = Reply::Kind::None;  // answered once the tracker has tried the box
      break;
    case CTP_CMD_RESET:
      app.requestReset();
      break;
    case CTP_CMD_STOP:
      app.requestStop();
      break;
    case CTP_CMD_SET_RATE:
      app.setRateHz(c.rate_hz);
      break;
    default:
      break;
  }
  return r;
}

}  // namespace cuetrack::app
