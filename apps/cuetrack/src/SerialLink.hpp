// cuetrack's own protocol as the app's TrackLink: frames in and out over a ByteStream
// through the shared transmit queue (QueuedPort: a stalled peer never blocks the
// tracker, drops are counted), the per-link sequence number, the output rate limit,
// heartbeats, and reconnecting when the device comes back.
#pragma once

#include <cstddef>
#include <cstdint>

#include "CommandHandler.hpp"
#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/QueuedPort.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackLink.hpp"
#include "cuetrack_proto.h"

namespace cuetrack::app {

using platform::LinkStats;

struct InboundEvent {
  int error = 0;  // CTP_OK: frame is valid; else CTP_E_CRC/FRAMING/VERSION
  ctp_frame_t frame{};
};

class SerialLink final : public platform::TrackLink {
 public:
  static constexpr uint64_t kHeartbeatPeriodUs = 1000000;

  SerialLink(platform::ByteStream& port, const Clock& clock, platform::Reporter& reporter);

  // TrackLink
  void poll(platform::LinkControl& control, const platform::LinkStatus& status) override;
  void sendFrame(const platform::FrameReport& report) override { sendTrack(report.track); }
  void answerStart(uint32_t token, platform::StartOutcome outcome) override;
  bool drain(int maxMs) override { return _port.drain(maxMs); }
  bool connected() const override { return _port.connected(); }
  const LinkStats& stats() const override { return _port.stats(); }

  // Reads what arrived (never waits) and decodes up to `max` events.
  size_t receive(InboundEvent* events, size_t max);
  // Flushes queued bytes and, while disconnected, retries the device every 0.5 s.
  void service();

  // TRACK, subject to the rate limit (by frame time). True when queued.
  bool sendTrack(ctp_track_t track);
  bool heartbeatDue() const;
  void sendHeartbeat(uint8_t state, uint32_t frames, uint8_t flags = 0);  // flags: CTP_HB_*
  void sendAck(uint8_t cmdType, uint16_t cmdId);
  void sendError(uint8_t cmdType, uint16_t cmdId, uint8_t code);
  void noteRejected() { ++_port.stats().rxErrors; }  // a frame decoded but malformed as a command

  void setRateHz(uint16_t hz) { _rateHz = hz; }
  uint16_t rateHz() const { return _rateHz; }
  const ctp_stats_t& decoderStats() const { return _decoder.stats; }
  const CommandHandler& commands() const { return _commands; }

 private:
  bool transmit(const uint8_t* wire, size_t n);  // a whole message, with its seq
  uint32_t nextSeq() const { return _seq; }
  void sendDelimiter();

  platform::QueuedPort _port;
  const Clock& _clock;
  ctp_decoder_t _decoder{};
  CommandHandler _commands;
  uint8_t _rx[256]{};
  size_t _rxPos{0}, _rxLen{0};
  uint32_t _seq{0};
  uint16_t _rateHz{0};
  bool _haveSentTrack{false};
  uint64_t _lastTrackTimeUs{0};
  bool _heartbeatTried{false};
  uint64_t _lastHeartbeatTryUs{0};  // sent or not: a congested line gets one try a second
};

}  // namespace cuetrack::app
