#include "SerialLink.hpp"

#include <cstring>

namespace cuetrack::app {

SerialLink::SerialLink(platform::ByteStream& port, const Clock& clock, platform::Reporter& reporter)
    : _port(port, clock, reporter), _clock(clock) {
  ctp_decoder_init(&_decoder);
  sendDelimiter();
}

// A lone delimiter ends whatever half frame the receiver holds from before.
void SerialLink::sendDelimiter() {
  const uint8_t zero = 0;
  _port.send(&zero, 1, false);
}

void SerialLink::service() {
  if (_port.service()) {
    ctp_decoder_init(&_decoder);
    _rxPos = _rxLen = 0;
    sendDelimiter();
  }
}

namespace {
// CommandHandler speaks AppControl; the pipeline listens as a LinkControl. SET_RATE stays
// with the link.
struct ControlAdapter final : AppControl {
  ControlAdapter(platform::LinkControl& c, SerialLink& l) : control(c), link(l) {}
  void requestStart(const Box& boxPx, uint16_t cmdId) override {
    platform::StartRequest r;
    r.kind = platform::StartRequest::Kind::BoxPx;
    r.box = boxPx;
    r.token = cmdId;
    control.requestStart(r);
  }
  void requestReset() override { control.requestReset(); }
  void requestStop() override { control.requestStop(); }
  void setRateHz(uint16_t hz) override { link.setRateHz(hz); }
  platform::LinkControl& control;
  SerialLink& link;
};
}  // namespace

void SerialLink::poll(platform::LinkControl& control, const platform::LinkStatus& status) {
  service();
  ControlAdapter app(control, *this);
  InboundEvent events[8];
  for (;;) {
    const size_t n = receive(events, 8);
    for (size_t i = 0; i < n; ++i) {
      const Reply r = _commands.handle(events[i].error, events[i].frame, app);
      if (r.kind == Reply::Kind::Ack) sendAck(r.cmdType, r.cmdId);
      if (r.kind == Reply::Kind::Error) {
        // The decoder already counted framing/CRC/version errors; count malformed commands here.
        if (events[i].error == CTP_OK) noteRejected();
        sendError(r.cmdType, r.cmdId, r.code);
      }
    }
    if (n < 8) break;
  }
  if (heartbeatDue())
    sendHeartbeat(status.state, status.frames, status.noCamera ? CTP_HB_NO_CAMERA : 0u);
}

void SerialLink::answerStart(uint32_t token, platform::StartOutcome outcome) {
  const uint16_t id = static_cast<uint16_t>(token);
  switch (outcome) {
    case platform::StartOutcome::Started:
      sendAck(CTP_CMD_START, id);
      break;
    case platform::StartOutcome::Refused:
      sendError(CTP_CMD_START, id, CTP_E_REJECTED);
      break;
    case platform::StartOutcome::Superseded:
      sendError(CTP_CMD_START, id, CTP_E_BUSY);
      break;
  }
}

size_t SerialLink::receive(InboundEvent* events, size_t max) {
  size_t count = 0;
  while (count < max && _port.connected()) {
    if (_rxPos == _rxLen) {
      const size_t got = _port.read(_rx, sizeof _rx);
      if (got == 0) break;
      _rxPos = 0;
      _rxLen = got;
    }
    while (_rxPos < _rxLen && count < max) {
      int err = 0;
      const int res = ctp_decoder_push(&_decoder, _rx[_rxPos++], &events[count].frame, &err);
      if (res == CTP_PUSH_FRAME) {
        events[count++].error = CTP_OK;
        ++_port.stats().rxFrames;
      } else if (res == CTP_PUSH_ERROR) {
        events[count++].error = err;
        ++_port.stats().rxErrors;
      }
    }
  }
  if (!_port.connected()) _rxPos = _rxLen = 0;
  return count;
}

// Every message takes the next seq whether or not it goes out: one the device cannot put
// on the line (queue full, link down) shows at the host as a gap in seq, and is counted.
bool SerialLink::transmit(const uint8_t* wire, size_t n) {
  ++_seq;
  return _port.send(wire, n);
}

bool SerialLink::sendTrack(ctp_track_t track) {
  if (_rateHz > 0 && _haveSentTrack) {
    const uint64_t periodUs = 1000000u / _rateHz;
    // 10 % slack: frame times jitter, and 30 fps at rate 15 must give every 2nd frame.
    if (track.time_us - _lastTrackTimeUs < periodUs - periodUs / 10) return false;
  }
  track.seq = nextSeq();
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_track(&track, wire, sizeof wire);
  if (!transmit(wire, n)) return false;
  _haveSentTrack = true;
  _lastTrackTimeUs = track.time_us;
  return true;
}

// Due after a second without anything on the line, and at most once a second by the
// clock: the time of the last write moves only when one succeeds, so on a congested line
// that alone would try (and drop, and count) a heartbeat on every frame.
bool SerialLink::heartbeatDue() const {
  const uint64_t now = _clock.nowUs();
  return _port.connected() && now - _port.lastTxUs() >= kHeartbeatPeriodUs &&
         (!_heartbeatTried || now - _lastHeartbeatTryUs >= kHeartbeatPeriodUs);
}

void SerialLink::sendHeartbeat(uint8_t state, uint32_t frames, uint8_t flags) {
  _heartbeatTried = true;
  _lastHeartbeatTryUs = _clock.nowUs();
  ctp_heartbeat_t h{};
  h.seq = nextSeq();
  h.time_us = _clock.nowUs();
  h.state = state;
  h.flags = flags;
  h.frames = frames;
  h.rx_errors = _port.stats().rxErrors;
  uint8_t wire[CTP_MAX_WIRE];
  transmit(wire, ctp_encode_heartbeat(&h, wire, sizeof wire));
}

void SerialLink::sendAck(uint8_t cmdType, uint16_t cmdId) {
  const ctp_ack_t a{nextSeq(), cmdType, cmdId};
  uint8_t wire[CTP_MAX_WIRE];
  transmit(wire, ctp_encode_ack(&a, wire, sizeof wire));
}

void SerialLink::sendError(uint8_t cmdType, uint16_t cmdId, uint8_t code) {
  const ctp_error_t e{nextSeq(), cmdType, cmdId, code};
  uint8_t wire[CTP_MAX_WIRE];
  transmit(wire, ctp_encode_error(&e, wire, sizeof wire));
}

}  // namespace cuetrack::app
