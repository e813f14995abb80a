#include "SerialLink.hpp"

#include <cstdio>
#include <cstring>

namespace cuetrack::app {

using platform::IoResult;
using platform::IoStatus;

SerialLink::SerialLink(platform::ByteStream& port, const Clock& clock, platform::Reporter& reporter)
    : _port(port), _clock(clock), _reporter(reporter) {
  ctp_decoder_init(&_decoder);
  _connected = _port.isOpen();
  _lastTxUs = _clock.nowUs();
  // A lone delimiter ends whatever half frame the receiver holds from before we started.
  const uint8_t zero = 0;
  enqueue(&zero, 1);
}

void SerialLink::lost(const char* why) {
  if (!_connected) return;
  _connected = false;
  ++_stats.disconnects;
  // The queued messages are lost with the line: count them (one 0x00 ends each frame).
  for (size_t i = 0; i < _txSize; ++i) _stats.txDropped += _tx[(_txHead + i) % kTxQueueBytes] == 0;
  _txHead = _txSize = 0;
  _rxPos = _rxLen = 0;
  _lastRetryUs = _clock.nowUs();
  char line[512];
  std::snprintf(line, sizeof line, "%s; tracking continues, retrying every %u ms", why,
                static_cast<unsigned>(kRetryPeriodUs / 1000));
  _reporter.report(line);
  _port.close();
}

void SerialLink::service() {
  if (!_connected) {
    const uint64_t now = _clock.nowUs();
    if (now - _lastRetryUs < kRetryPeriodUs) return;
    _lastRetryUs = now;
    if (!_port.reopen()) return;
    _connected = true;
    ++_stats.reconnects;
    ctp_decoder_init(&_decoder);
    char line[320];
    std::snprintf(line, sizeof line, "%s: reconnected", _port.name());
    _reporter.report(line);
    const uint8_t zero = 0;
    enqueue(&zero, 1);
  }
  flush();
}

bool SerialLink::drain(int maxMs) {
  // Bounded by iterations, not by the clock: a fake clock in tests does not move.
  for (int waitedMs = 0; _connected && _txSize > 0 && waitedMs < maxMs; waitedMs += 10) {
    if (_port.waitWritable(10)) flush();
  }
  return _txSize == 0;
}

void SerialLink::flush() {
  while (_connected && _txSize > 0) {
    const size_t contiguous =
        (_txHead + _txSize <= kTxQueueBytes) ? _txSize : kTxQueueBytes - _txHead;
    const IoResult r = _port.write(_tx + _txHead, contiguous);
    if (r.status == IoStatus::Closed || r.status == IoStatus::Error) {
      lost(_port.error());
      return;
    }
    if (r.status == IoStatus::WouldBlock || r.bytes == 0) return;
    _txHead = (_txHead + r.bytes) % kTxQueueBytes;
    _txSize -= r.bytes;
  }
}

bool SerialLink::enqueue(const uint8_t* bytes, size_t n) {
  if (!_connected || kTxQueueBytes - _txSize < n) return false;
  for (size_t i = 0; i < n; ++i) _tx[(_txHead + _txSize + i) % kTxQueueBytes] = bytes[i];
  _txSize += n;
  _lastTxUs = _clock.nowUs();
  flush();
  return true;
}

size_t SerialLink::receive(InboundEvent* events, size_t max) {
  size_t count = 0;
  while (count < max && _connected) {
    if (_rxPos == _rxLen) {
      const IoResult r = _port.read(_rx, sizeof _rx, 0);
      if (r.status == IoStatus::Closed || r.status == IoStatus::Error) {
        lost(_port.error());
        break;
      }
      if (r.bytes == 0) break;
      _rxPos = 0;
      _rxLen = r.bytes;
    }
    while (_rxPos < _rxLen && count < max) {
      int err = 0;
      const int res = ctp_decoder_push(&_decoder, _rx[_rxPos++], &events[count].frame, &err);
      if (res == CTP_PUSH_FRAME) {
        events[count++].error = CTP_OK;
        ++_stats.rxFrames;
      } else if (res == CTP_PUSH_ERROR) {
        events[count++].error = err;
        ++_stats.rxErrors;
      }
    }
  }
  return count;
}

// Every message takes the next seq whether or not it goes out: one the device cannot put
// on the line (queue full, link down) shows at the host as a gap in seq, and is counted.
bool SerialLink::transmit(const uint8_t* wire, size_t n) {
  ++_seq;
  if (enqueue(wire, n)) {
    ++_stats.sent;
    return true;
  }
  ++_stats.txDropped;
  return false;
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

bool SerialLink::heartbeatDue() const {
  return _connected && _clock.nowUs() - _lastTxUs >= kHeartbeatPeriodUs;
}

void SerialLink::sendHeartbeat(uint8_t state, uint32_t frames, uint8_t flags) {
  ctp_heartbeat_t h{};
  h.seq = nextSeq();
  h.time_us = _clock.nowUs();
  h.state = state;
  h.flags = flags;
  h.frames = frames;
  h.rx_errors = _stats.rxErrors;
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
