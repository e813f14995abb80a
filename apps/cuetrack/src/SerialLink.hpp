// The serial side of the app: frames in and out over a ByteStream, a small transmit
// queue so a slow or stalled peer never blocks the tracker (messages that do not fit
// are dropped and counted), the per-link sequence number, the output rate limit,
// heartbeats, and reconnecting when the device comes back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/Clock.hpp"
#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::app {

struct InboundEvent {
  int error = 0;  // CTP_OK: frame is valid; else CTP_E_CRC/FRAMING/VERSION
  ctp_frame_t frame{};
};

struct LinkStats {
  uint32_t sent = 0;       // messages queued for the line
  uint32_t txDropped = 0;  // messages dropped: line too slow, or disconnected
  uint32_t rxFrames = 0;   // good inbound frames
  uint32_t rxErrors =
      0;  // rejected inbound frames (framing, CRC, version; malformed via noteRejected)
  uint32_t disconnects = 0;
  uint32_t reconnects = 0;
};

class SerialLink {
 public:
  static constexpr size_t kTxQueueBytes = 2048;
  static constexpr uint64_t kHeartbeatPeriodUs = 1000000;
  static constexpr uint64_t kRetryPeriodUs = 500000;

  SerialLink(platform::ByteStream& port, const Clock& clock, platform::Reporter& reporter);

  // Reads what arrived (never waits) and decodes up to `max` events.
  size_t receive(InboundEvent* events, size_t max);
  // Flushes queued bytes and, while disconnected, retries the device every 0.5 s.
  void service();
  // At exit: waits (at most ~maxMs) until the queue is on the line, so a last ACK or
  // track is not lost. Returns true when the queue is empty.
  bool drain(int maxMs);

  // TRACK, subject to the rate limit (by frame time). True when queued.
  bool sendTrack(ctp_track_t track);
  bool heartbeatDue() const;
  void sendHeartbeat(uint8_t state, uint32_t frames, uint8_t flags = 0);  // flags: CTP_HB_*
  void sendAck(uint8_t cmdType, uint16_t cmdId);
  void sendError(uint8_t cmdType, uint16_t cmdId, uint8_t code);
  void noteRejected() { ++_stats.rxErrors; }  // a frame decoded but malformed as a command

  void setRateHz(uint16_t hz) { _rateHz = hz; }
  uint16_t rateHz() const { return _rateHz; }
  bool connected() const { return _connected; }
  const LinkStats& stats() const { return _stats; }
  const ctp_stats_t& decoderStats() const { return _decoder.stats; }

 private:
  bool enqueue(const uint8_t* bytes, size_t n);
  bool transmit(const uint8_t* wire, size_t n);  // a whole message, with its seq
  uint32_t nextSeq() const { return _seq; }
  void lost(const char* why);
  void flush();

  platform::ByteStream& _port;
  const Clock& _clock;
  platform::Reporter& _reporter;
  ctp_decoder_t _decoder{};
  uint8_t _tx[kTxQueueBytes]{};
  size_t _txHead{0}, _txSize{0};
  uint8_t _rx[256]{};
  size_t _rxPos{0}, _rxLen{0};
  uint32_t _seq{0};
  uint16_t _rateHz{0};
  bool _haveSentTrack{false};
  uint64_t _lastTrackTimeUs{0};
  uint64_t _lastTxUs{0};
  uint64_t _lastRetryUs{0};
  bool _connected{true};
  LinkStats _stats{};
};

}  // namespace cuetrack::app
