// MAVLink 2 as the app's TrackLink: cuetrack as a camera component (MAV_TYPE_CAMERA) that
// PX4, ArduPilot and QGroundControl understand. Over the same transmit queue as
// cuetrack's own protocol (QueuedPort: a stalled autopilot never blocks the tracker,
// drops are counted, the device is retried when it goes away).
//   out: HEARTBEAT at 1 Hz; CAMERA_TRACKING_IMAGE_STATUS every frame (or at the interval
//        MAV_CMD_SET_MESSAGE_INTERVAL sets); LANDING_TARGET while tracking in 3D;
//        CAMERA_INFORMATION on MAV_CMD_REQUEST_MESSAGE; one COMMAND_ACK per command.
//   in:  COMMAND_LONG: CAMERA_TRACK_RECTANGLE, CAMERA_TRACK_POINT, CAMERA_STOP_TRACKING,
//        SET_MESSAGE_INTERVAL, REQUEST_MESSAGE. Others addressed to us: UNSUPPORTED.
//        Only from the accepted system ids (when given); broadcasts only where the camera
//        protocol allows them; the rest refused without an answer and counted.
// Over a datagram stream (UDP) each datagram is parsed on its own, and every poll reads
// the datagrams waiting, up to a bound that keeps the frame rate. Output is paced to the
// link's rate (LinkConfig::outputBytesPerS): answers wait in a queue, telemetry that finds
// no room is dropped and counted, the heartbeat waits for room.
// docs/mavlink.md describes every field.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/core/base/Clock.hpp"
#include "cuetrack/platform/ByteStream.hpp"
#include "cuetrack/platform/QueuedPort.hpp"
#include "cuetrack/platform/Reporter.hpp"
#include "cuetrack/platform/TrackLink.hpp"
#include "cuetrack/platform/mavlink/CameraMount.hpp"
#include "cuetrack/platform/mavlink/MavlinkCodec.hpp"
#include "cuetrack/platform/mavlink/MavlinkMessages.hpp"
#include "cuetrack/platform/mavlink/Signing.hpp"

namespace cuetrack::platform::mavlink {

struct LinkConfig {
  static constexpr int kMaxAcceptedSysIds = 8;
  // A UDP ground station's default output rate: about a 921600-baud line. A burst at this
  // rate (50 ms of it, a hundred small datagrams) fits an ordinary receive buffer (208 KB
  // by default on Linux, about 260 datagrams).
  static constexpr uint32_t kDefaultOutputBytesPerS = 100000;
  uint8_t sysId = 1;                  // the vehicle's system id (the autopilot's, usually 1)
  uint8_t compId = kMavCompIdCamera;  // our component id
  // Commands are obeyed only from these senders' system ids (--mavlink-accept-sysid);
  // none given: from any.
  uint8_t acceptSysIds[kMaxAcceptedSysIds]{};
  int acceptSysIdCount = 0;
  // MAVLink 2 signing (--mavlink-key): our messages signed with this link id; commands
  // obeyed only when signed with the key, and newer than their stream's last (replays).
  bool signing = false;
  SigningKey key{};
  uint8_t linkId = 0;
  // The signing timestamp at construction (10 us units since 2015-01-01, from the wall
  // clock; 0 when it is not known): then moved on by the link's clock.
  uint64_t signingTimestamp = 0;
  // The link's output rate [bytes/s] (--mavlink-rate; on serial the app gives the baud
  // rate / 10): answers wait for it, telemetry that finds no room is dropped and counted.
  uint32_t outputBytesPerS = kDefaultOutputBytesPerS;
  CameraMount mount{};
  // LANDING_TARGET with x, y, z in MAV_FRAME_BODY_FRD (ArduPilot); false: angles and
  // distance only, position_valid 0 (PX4 reads only that, as an IRLock-style report).
  bool landingPosition = true;
};

class MavlinkLink final : public TrackLink {
 public:
  static constexpr uint64_t kHeartbeatPeriodUs = 1000000;  // MAVLink's 1 Hz
  // One poll reads at most this many datagrams, or past this many bytes no further one
  // (a whole datagram is always parsed): a flood costs a frame a millisecond or two, and
  // what the kernel then drops is counted. 100 messages/s are a few datagrams a frame.
  static constexpr int kMaxDatagramsPerPoll = 256;
  static constexpr size_t kMaxRxBytesPerPoll = 128 * 1024;
  static constexpr size_t kRxBufferBytes = 65535;  // the largest UDP datagram
  // Output pacing: the budget holds at most this much of the rate (and one whole frame),
  // so a burst of answers leaves over several polls rather than at once.
  static constexpr uint64_t kBurstUs = 50000;
  static constexpr size_t kUdpOverheadBytes = 28;  // IPv4 and UDP headers, per datagram
  static constexpr int kMaxWaitingAnswers = 256;   // ACKs waiting for the rate; more dropped

  MavlinkLink(ByteStream& port, const Clock& clock, Reporter& reporter, const LinkConfig& config);

  // TrackLink
  void poll(LinkControl& control, const LinkStatus& status) override;
  void sendFrame(const FrameReport& report) override;
  void answerStart(uint32_t token, StartOutcome outcome) override;
  bool drain(int maxMs) override;
  bool connected() const override { return _port.connected(); }
  const LinkStats& stats() const override { return _port.stats(); }

  const ParserStats& parserStats() const { return _parser.stats(); }

 private:
  // A message interval as MAV_CMD_SET_MESSAGE_INTERVAL sets it, applied by frame time.
  struct Interval {
    int64_t us = 0;  // 0: every frame; -1: off
    bool sent = false;
    uint64_t lastUs = 0;
    bool due(uint64_t nowUs);
  };
  // A track command waiting for the tracker's answer on the next frame.
  struct PendingStart {
    bool used = false;
    uint32_t token = 0;
    uint16_t command = 0;
    uint8_t mode = 0;  // kTrackingMode*
    uint8_t sysId = 0, compId = 0;
  };
  static constexpr int kPendingSlots = 2;  // the old one is answered as the new one arrives

  enum class Addressing : uint8_t { NotOurs, ToUs, Broadcast };
  Addressing addressing(uint8_t targetSystem, uint8_t targetComponent) const;
  bool accepted(uint8_t fromSys) const;
  bool broadcastAllowed(const CommandLong& c) const;
  void pollBytes(LinkControl& control);
  void pollDatagrams(LinkControl& control);
  void countParserErrors();
  void received(const Message& m, LinkControl& control);
  void handle(const Message& m, LinkControl& control);
  void handleCommand(const CommandLong& c, uint8_t fromSys, uint8_t fromComp, bool broadcast,
                     LinkControl& control);
  uint8_t startTracking(const CommandLong& c, uint8_t fromSys, uint8_t fromComp, bool broadcast,
                        LinkControl& control);
  uint8_t setInterval(const CommandLong& c);
  bool transmit(uint32_t msgId, const uint8_t* payload, size_t len);
  bool affordable(uint32_t msgId);     // the budget holds msgId's largest frame
  bool telemetryFits(uint32_t msgId);  // no answer waits, and affordable
  void dropped();
  void pump(bool paced = true);  // waiting answers out, as the budget allows
  void sendAck(uint16_t command, uint8_t result, uint8_t toSys, uint8_t toComp);
  void transmitAck(uint16_t command, uint8_t result, uint8_t toSys, uint8_t toComp);
  bool sendHeartbeat(const LinkStatus& status);
  void sendCameraInformation();
  void sendStatus(const FrameReport& r);
  void sendLandingTarget(const FrameReport& r);

  struct Answer {
    uint16_t command;
    uint8_t result, sysId, compId;
  };

  uint64_t signingClock() const;
  bool nextSigningTimestamp(uint64_t* out);

  QueuedPort _port;
  const Clock& _clock;
  LinkConfig _config;
  Parser _parser;
  uint32_t _errorsCounted{0};  // of the parser's errors, already in rx-errors
  SignatureChecker _signatures;
  uint64_t _lastSignedTimestamp{0};
  uint64_t _clockBase{0};  // signing units at _clockBaseUs; 0: our clock is not known
  uint64_t _clockBaseUs{0};
  uint8_t _rx[kRxBufferBytes]{};
  uint8_t _seq{0};
  bool _heartbeatSent{false};
  uint64_t _lastHeartbeatUs{0};
  uint64_t _startUs{0};
  uint32_t _nextToken{1};
  PendingStart _pending[kPendingSlots]{};
  uint8_t _trackingMode{kTrackingModeNone};
  Interval _statusInterval{}, _landingInterval{};
  int _widthPx{0}, _heightPx{0};  // of the last frame, for CAMERA_INFORMATION
  Answer _answers[kMaxWaitingAnswers]{};
  int _answerHead{0}, _answerCount{0};
  bool _infoWaiting{false};  // CAMERA_INFORMATION, once after the ACKs waiting
  bool _infoSentThisPoll{false};
  double _budgetBytes{0.};
  uint64_t _budgetUs{0};
};

}  // namespace cuetrack::platform::mavlink
