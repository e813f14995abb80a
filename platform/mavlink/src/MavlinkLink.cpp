#include "cuetrack/platform/mavlink/MavlinkLink.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>

namespace cuetrack::platform::mavlink {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr uint32_t kFirmwareVersion = 0x00000100;  // 0.1.0 as (patch << 16) | (minor << 8) | major
constexpr int64_t kIntervalOff = -1;
constexpr uint8_t kDeferred = 0xFF;  // not a MAV_RESULT: the ACK waits for the tracker

bool inUnit(float v) {
  return std::isfinite(v) && v >= 0.f && v <= 1.f;
}

// A command's "target camera id": 0 (all cameras), NaN (not given, as some senders mark
// an unused parameter) or our component id. A broadcast command must name 0: the camera
// protocol has every other id NACKed with DENIED.
bool cameraIsUs(float id, uint8_t compId, bool broadcast) {
  if (broadcast) return id == 0.f;
  return std::isnan(id) || id == 0.f || id == static_cast<float>(compId);
}

}  // namespace

bool MavlinkLink::Interval::due(uint64_t nowUs) {
  if (us < 0) return false;
  // 10 % slack: frame times jitter, and 30 fps at 66,666 us must give every 2nd frame.
  const uint64_t periodUs = static_cast<uint64_t>(us);
  if (sent && nowUs - lastUs < periodUs - periodUs / 10) return false;
  sent = true;
  lastUs = nowUs;
  return true;
}

MavlinkLink::MavlinkLink(ByteStream& port, const Clock& clock, Reporter& reporter,
                         const LinkConfig& config)
    : _port(port, clock, reporter), _clock(clock), _config(config), _signatures(config.key) {
  _startUs = _clock.nowUs();
  _clockBase = config.signingTimestamp;
  _clockBaseUs = _startUs;
  _budgetUs = _startUs;
  _budgetBytes = 1e300;  // full: clipped to the burst at the first refill
}

bool MavlinkLink::affordable(uint32_t msgId) {
  const double rate = static_cast<double>(_config.outputBytesPerS);
  const double overhead = _port.datagrams() ? static_cast<double>(kUdpOverheadBytes) : 0.;
  const double frameMax = static_cast<double>(kMaxFrameBytes) + overhead;
  const double cap = std::max(rate * static_cast<double>(kBurstUs) * 1e-6, frameMax);
  const uint64_t now = _clock.nowUs();
  _budgetBytes = std::min(cap, _budgetBytes + rate * static_cast<double>(now - _budgetUs) * 1e-6);
  _budgetUs = now;
  const MessageInfo* info = messageInfo(msgId);
  const double worst = static_cast<double>(kHeaderBytes + (info ? info->payloadBytes : 0) +
                                           kCrcBytes + (_config.signing ? kSignatureBytes : 0)) +
                       overhead;
  return _budgetBytes >= worst;
}

// A message that cannot go out: counted, and its seq skipped (the receiver sees the gap).
void MavlinkLink::dropped() {
  ++_seq;
  ++_port.stats().txDropped;
}

bool MavlinkLink::telemetryFits(uint32_t msgId) {
  return _answerCount == 0 && !_infoWaiting && affordable(msgId);
}

// The answers waiting, oldest first, then CAMERA_INFORMATION once however many asked.
void MavlinkLink::pump(bool paced) {
  while (_answerCount > 0 && (!paced || affordable(kMsgCommandAck))) {
    const Answer a = _answers[_answerHead];
    _answerHead = (_answerHead + 1) % kMaxWaitingAnswers;
    --_answerCount;
    transmitAck(a.command, a.result, a.sysId, a.compId);
  }
  if (_answerCount == 0 && _infoWaiting && (!paced || affordable(kMsgCameraInformation))) {
    _infoWaiting = false;
    _infoSentThisPoll = true;
    sendCameraInformation();
  }
}

// At exit: what waits goes out at once, then the queue drains.
bool MavlinkLink::drain(int maxMs) {
  pump(false);
  return _port.drain(maxMs);
}

bool MavlinkLink::transmit(uint32_t msgId, const uint8_t* payload, size_t len) {
  Header h;
  h.seq = _seq++;  // a message that cannot go out leaves a gap in seq: the peer sees the drop
  h.sysId = _config.sysId;
  h.compId = _config.compId;
  h.msgId = msgId;
  uint8_t wire[kMaxFrameBytes];
  uint64_t timestamp = 0;
  if (_config.signing && !nextSigningTimestamp(&timestamp)) {
    ++_port.stats().txDropped;  // past 2^48 - 1: dropped rather than wrapped
    return false;
  }
  const size_t n = _config.signing ? encodeSignedFrame(h, payload, len, _config.key, _config.linkId,
                                                       timestamp, wire, sizeof wire)
                                   : encodeFrame(h, payload, len, wire, sizeof wire);
  _budgetBytes -= static_cast<double>(n + (_port.datagrams() ? kUdpOverheadBytes : 0));
  return n > 0 && _port.send(wire, n);
}

// Our clock in signing units: the wall clock's time at start (or the first timestamp we
// believed, on a board whose clock is not set) moved on by the link's clock.
uint64_t MavlinkLink::signingClock() const {
  return _clockBase + (_clock.nowUs() - _clockBaseUs) / 10;
}

// Our clock, never behind what we signed or saw last (the spec's rule for a system whose
// clock is not set), never past 2^48 - 1: false then, nothing is signed.
bool MavlinkLink::nextSigningTimestamp(uint64_t* out) {
  uint64_t t = signingClock();
  if (t <= _lastSignedTimestamp) t = _lastSignedTimestamp + 1;
  if (t <= _signatures.newest()) t = _signatures.newest() + 1;
  if (t > kSigningMaxTimestamp) return false;
  _lastSignedTimestamp = t;
  _signatures.noteTimestamp(t);
  *out = t;
  return true;
}

void MavlinkLink::poll(LinkControl& control, const LinkStatus& status) {
  if (_port.service()) _parser.reset();
  _infoSentThisPoll = false;
  // The heartbeat first: a stream of answers waiting must not starve it.
  const uint64_t now = _clock.nowUs();
  if (_port.connected() && (!_heartbeatSent || now - _lastHeartbeatUs >= kHeartbeatPeriodUs)) {
    if (sendHeartbeat(status)) {  // else it waits for room, tried again next poll
      _heartbeatSent = true;
      _lastHeartbeatUs = now;
    }
  }
  pump();  // then the answers waiting from before
  if (_port.datagrams()) {
    pollDatagrams(control);
  } else {
    pollBytes(control);
  }
}

// A serial line: a byte stream, frames may straddle reads.
void MavlinkLink::pollBytes(LinkControl& control) {
  for (;;) {
    const size_t got = _port.read(_rx, sizeof _rx);
    for (size_t i = 0; i < got; ++i) {
      Message m;
      for (bool ready = _parser.push(_rx[i], &m); ready; ready = _parser.next(&m))
        received(m, control);
    }
    countParserErrors();
    if (got < sizeof _rx) break;
  }
}

// UDP: each datagram on its own (noise in one cannot swallow a frame in the next), as
// many as wait, up to the poll's bound.
void MavlinkLink::pollDatagrams(LinkControl& control) {
  size_t bytes = 0;
  for (int d = 0; d < kMaxDatagramsPerPoll && bytes < kMaxRxBytesPerPoll; ++d) {
    const size_t got = _port.read(_rx, sizeof _rx);
    if (got == 0) break;
    bytes += got;
    size_t at = 0;
    Message m;
    while (_parser.nextInDatagram(_rx, got, &at, &m)) received(m, control);
    countParserErrors();
  }
}

// The parser's new discarded runs into the link's rx-errors, by reason.
void MavlinkLink::countParserErrors() {
  const ParserStats& p = _parser.stats();
  LinkStats& s = _port.stats();
  s.rxErrors += p.totalErrors() - _errorsCounted;
  _errorsCounted = p.totalErrors();
  s.rxBadCrc = p.badCrc();
  s.rxBadLength = p.badLength();
  s.rxBadUnknown = p.badUnknown();
}

void MavlinkLink::received(const Message& m, LinkControl& control) {
  ++_port.stats().rxFrames;
  handle(m, control);
}

// Commands for another system or component are not ours to answer; system or component 0
// addresses everyone.
MavlinkLink::Addressing MavlinkLink::addressing(uint8_t targetSystem,
                                                uint8_t targetComponent) const {
  if ((targetSystem != 0 && targetSystem != _config.sysId) ||
      (targetComponent != 0 && targetComponent != _config.compId))
    return Addressing::NotOurs;
  return targetSystem == _config.sysId && targetComponent == _config.compId ? Addressing::ToUs
                                                                            : Addressing::Broadcast;
}

bool MavlinkLink::accepted(uint8_t fromSys) const {
  if (_config.acceptSysIdCount == 0) return true;
  for (int i = 0; i < _config.acceptSysIdCount; ++i)
    if (_config.acceptSysIds[i] == fromSys) return true;
  return false;
}

// What the camera protocol lets everyone ask of every camera: CAMERA_INFORMATION (discovery)
// and the tracking commands, which then must name camera 0 (checked with their parameters).
// SET_MESSAGE_INTERVAL would change our stream for whoever asked everyone: refused.
bool MavlinkLink::broadcastAllowed(const CommandLong& c) const {
  switch (c.command) {
    case kCmdCameraTrackRectangle:
    case kCmdCameraTrackPoint:
    case kCmdCameraStopTracking:
      return true;
    case kCmdRequestMessage:
      return c.param[0] == static_cast<float>(kMsgCameraInformation);
    default:
      return false;
  }
}

void MavlinkLink::handle(const Message& m, LinkControl& control) {
  if (m.header.msgId != kMsgCommandLong && m.header.msgId != kMsgCommandInt) return;
  const bool isLong = m.header.msgId == kMsgCommandLong;
  const CommandLong c = isLong ? unpackCommandLong(m.payload) : CommandLong{};
  const CommandInt ci = isLong ? CommandInt{} : unpackCommandInt(m.payload);
  const Addressing to = isLong ? addressing(c.targetSystem, c.targetComponent)
                               : addressing(ci.targetSystem, ci.targetComponent);
  if (to == Addressing::NotOurs) return;
  // With a key: unsigned, badly signed and replayed commands are not obeyed, not answered.
  if (_config.signing) {
    const bool clockKnown = _clockBase != 0;
    if (_signatures.check(m, clockKnown ? signingClock() : 0) != SignatureCheck::Good) {
      ++_port.stats().rxRefused;
      return;
    }
    if (!clockKnown) {  // a board whose clock is not set: the first believable time is ours
      _clockBase = _signatures.newest();
      _clockBaseUs = _clock.nowUs();
    }
  }
  if (!accepted(m.header.sysId)) {  // a stranger: no answer, it learns nothing
    ++_port.stats().rxRefused;
    return;
  }
  if (to == Addressing::Broadcast && (!isLong || !broadcastAllowed(c))) {
    // No answer (every component would ACK otherwise); counted as refused when we would
    // obey it addressed to us, else it is someone else's (an autopilot's mission camera
    // commands, requests for other messages).
    if (isLong && c.command == kCmdSetMessageInterval) ++_port.stats().rxRefused;
    return;
  }
  if (isLong) {
    handleCommand(c, m.header.sysId, m.header.compId, to == Addressing::Broadcast, control);
  } else {
    sendAck(ci.command, kResultCommandLongOnly, m.header.sysId, m.header.compId);
  }
}

void MavlinkLink::handleCommand(const CommandLong& c, uint8_t fromSys, uint8_t fromComp,
                                bool broadcast, LinkControl& control) {
  uint8_t result = kResultUnsupported;
  switch (c.command) {
    case kCmdCameraTrackRectangle:
    case kCmdCameraTrackPoint:
      result = startTracking(c, fromSys, fromComp, broadcast, control);
      if (result == kDeferred) return;  // answered once the tracker has tried it
      break;
    case kCmdCameraStopTracking:
      if (!cameraIsUs(c.param[0], _config.compId, broadcast)) {
        result = kResultDenied;
        ++_port.stats().rxRefused;
        break;
      }
      control.requestReset();
      _trackingMode = kTrackingModeNone;
      result = kResultAccepted;
      break;
    case kCmdSetMessageInterval:
      result = setInterval(c);
      break;
    case kCmdRequestMessage:
      if (c.param[0] == static_cast<float>(kMsgCameraInformation)) {
        // After the ACK; once a poll however many asked (one message serves them all).
        if (!_infoSentThisPoll) _infoWaiting = true;
        sendAck(c.command, kResultAccepted, fromSys, fromComp);
        return;
      }
      result = kResultDenied;  // a message we do not send on request
      break;
    default:
      break;
  }
  sendAck(c.command, result, fromSys, fromComp);
}

uint8_t MavlinkLink::startTracking(const CommandLong& c, uint8_t fromSys, uint8_t fromComp,
                                   bool broadcast, LinkControl& control) {
  StartRequest r;
  float camera = 0.f;
  if (c.command == kCmdCameraTrackRectangle) {
    const float x0 = c.param[0], y0 = c.param[1], x1 = c.param[2], y1 = c.param[3];
    camera = c.param[4];
    if (!inUnit(x0) || !inUnit(y0) || !inUnit(x1) || !inUnit(y1) || !(x1 > x0) || !(y1 > y0))
      return kResultDenied;
    r.kind = StartRequest::Kind::BoxNormalised;
    r.box = Box{x0, y0, x1 - x0, y1 - y0};
  } else {
    camera = c.param[3];
    const float radius = std::isnan(c.param[2]) ? 0.f : c.param[2];  // NaN: not given
    if (!inUnit(c.param[0]) || !inUnit(c.param[1]) || !inUnit(radius)) return kResultDenied;
    r.kind = StartRequest::Kind::PointNormalised;
    r.pointX = c.param[0];
    r.pointY = c.param[1];
    r.radius = radius;
  }
  if (!cameraIsUs(camera, _config.compId, broadcast)) {
    ++_port.stats().rxRefused;
    return kResultDenied;
  }
  // A free slot: the pipeline answers the older pending start (Superseded) before it
  // keeps this one, so at most two are ever waiting.
  PendingStart* slot = nullptr;
  for (PendingStart& p : _pending)
    if (!p.used) slot = &p;
  if (slot == nullptr) return kResultTemporarilyRejected;
  r.token = _nextToken++;
  *slot = PendingStart{
      true,
      r.token,
      c.command,
      c.command == kCmdCameraTrackRectangle ? kTrackingModeRectangle : kTrackingModePoint,
      fromSys,
      fromComp};
  control.requestStart(r);
  return kDeferred;
}

void MavlinkLink::answerStart(uint32_t token, StartOutcome outcome) {
  for (PendingStart& p : _pending) {
    if (!p.used || p.token != token) continue;
    p.used = false;
    uint8_t result = kResultAccepted;
    if (outcome == StartOutcome::Refused) result = kResultDenied;
    if (outcome == StartOutcome::Superseded) result = kResultCancelled;
    if (outcome == StartOutcome::Started) _trackingMode = p.mode;
    sendAck(p.command, result, p.sysId, p.compId);
    return;
  }
}

uint8_t MavlinkLink::setInterval(const CommandLong& c) {
  const float id = c.param[0], us = c.param[1];
  Interval* target = nullptr;
  if (id == static_cast<float>(kMsgCameraTrackingImageStatus)) target = &_statusInterval;
  if (id == static_cast<float>(kMsgLandingTarget)) target = &_landingInterval;
  if (target == nullptr || !std::isfinite(us) || us < -1.f || us > 1e9f) return kResultDenied;
  target->us = us < 0.f ? kIntervalOff : static_cast<int64_t>(us);  // 0: the default, every frame
  target->sent = false;
  return kResultAccepted;
}

// Every answer waits its turn (the output rate); only when kMaxWaitingAnswers wait is one
// dropped, and counted.
void MavlinkLink::sendAck(uint16_t command, uint8_t result, uint8_t toSys, uint8_t toComp) {
  if (_answerCount == kMaxWaitingAnswers) {
    dropped();
    return;
  }
  _answers[(_answerHead + _answerCount) % kMaxWaitingAnswers] =
      Answer{command, result, toSys, toComp};
  ++_answerCount;
  pump();
}

void MavlinkLink::transmitAck(uint16_t command, uint8_t result, uint8_t toSys, uint8_t toComp) {
  CommandAck a;
  a.command = command;
  a.result = result;
  a.targetSystem = toSys;
  a.targetComponent = toComp;
  uint8_t p[16];
  transmit(kMsgCommandAck, p, pack(a, p));
}

// system_status: BOOT while no camera, ACTIVE while a target is tracked, else STANDBY;
// custom_mode: cuetrack's own state (CTP_STATE_*), | 0x100 while no camera.
bool MavlinkLink::sendHeartbeat(const LinkStatus& status) {
  if (!affordable(kMsgHeartbeat)) return false;
  Heartbeat h;
  h.type = kMavTypeCamera;
  h.autopilot = kMavAutopilotInvalid;
  h.systemStatus = status.noCamera                      ? kMavStateBoot
                   : status.state == CTP_STATE_TRACKING ? kMavStateActive
                                                        : kMavStateStandby;
  h.customMode = status.state | (status.noCamera ? 0x100u : 0u);
  uint8_t p[16];
  transmit(kMsgHeartbeat, p, pack(h, p));
  return true;
}

void MavlinkLink::sendCameraInformation() {
  CameraInformation ci;
  ci.timeBootMs = static_cast<uint32_t>((_clock.nowUs() - _startUs) / 1000);
  ci.firmwareVersion = kFirmwareVersion;
  ci.focalLength = kNaN;  // in mm: the intrinsics are in px
  ci.sensorSizeH = kNaN;
  ci.sensorSizeV = kNaN;
  ci.flags = kCameraCapHasTrackingPoint | kCameraCapHasTrackingRectangle;
  ci.resolutionH = static_cast<uint16_t>(_widthPx);
  ci.resolutionV = static_cast<uint16_t>(_heightPx);
  std::snprintf(ci.vendorName, sizeof ci.vendorName, "cuetrack");
  std::snprintf(ci.modelName, sizeof ci.modelName, "RGB-D tracker");
  uint8_t p[240];
  transmit(kMsgCameraInformation, p, pack(ci, p));
}

void MavlinkLink::sendFrame(const FrameReport& r) {
  _widthPx = r.widthPx;
  _heightPx = r.heightPx;
  if (_statusInterval.due(r.track.time_us)) sendStatus(r);
  const bool located = r.track.state == CTP_STATE_TRACKING &&
                       (r.track.flags & CTP_FLAG_HAS_3D) != 0 && r.intrinsics.valid();
  if (located && _landingInterval.due(r.track.time_us)) sendLandingTarget(r);
}

// The box as fractions of the image. While lost (ERROR) it is the last confirmed box (the
// pipeline puts it in the track, as for every output: issue 43), so that a consumer that
// reads the box without the status steers at where the target was last seen, never at the
// search's windows; NaN while idle or before any box.
void MavlinkLink::sendStatus(const FrameReport& r) {
  if (!telemetryFits(kMsgCameraTrackingImageStatus)) {  // stale by the next frame: dropped
    dropped();
    return;
  }
  CameraTrackingImageStatus s;
  s.targetData = kTrackingTargetDataInStatus;
  s.pointX = s.pointY = s.radius = kNaN;
  s.recTopX = s.recTopY = s.recBottomX = s.recBottomY = kNaN;
  const ctp_track_t& t = r.track;
  if (t.state == CTP_STATE_IDLE) {
    s.trackingStatus = kTrackingStatusIdle;
    s.trackingMode = kTrackingModeNone;
  } else {
    const bool tracking = t.state == CTP_STATE_TRACKING;
    s.trackingStatus = tracking ? kTrackingStatusActive : kTrackingStatusError;
    // Started from ground truth or --box: reported as a rectangle.
    s.trackingMode = _trackingMode == kTrackingModeNone ? kTrackingModeRectangle : _trackingMode;
    if (r.widthPx > 0 && r.heightPx > 0 && t.box_px[2] > 0 && t.box_px[3] > 0) {
      const float w = static_cast<float>(r.widthPx), h = static_cast<float>(r.heightPx);
      s.recTopX = static_cast<float>(t.box_px[0]) / w;
      s.recTopY = static_cast<float>(t.box_px[1]) / h;
      s.recBottomX = static_cast<float>(t.box_px[0] + t.box_px[2]) / w;
      s.recBottomY = static_cast<float>(t.box_px[1] + t.box_px[3]) / h;
      s.pointX = 0.5f * (s.recTopX + s.recBottomX);
      s.pointY = 0.5f * (s.recTopY + s.recBottomY);
      const float sidePx =
          static_cast<float>(t.box_px[2] > t.box_px[3] ? t.box_px[2] : t.box_px[3]);
      s.radius = 0.5f * sidePx / w;
    }
  }
  uint8_t p[40];
  transmit(kMsgCameraTrackingImageStatus, p, pack(s, p));
}

void MavlinkLink::sendLandingTarget(const FrameReport& r) {
  if (!telemetryFits(kMsgLandingTarget)) {
    dropped();
    return;
  }
  const ctp_track_t& t = r.track;
  const CameraIntrinsics& k = r.intrinsics;
  const float uPx = static_cast<float>(t.box_px[0]) + 0.5f * static_cast<float>(t.box_px[2]);
  const float vPx = static_cast<float>(t.box_px[1]) + 0.5f * static_cast<float>(t.box_px[3]);
  LandingTarget lt;
  lt.timeUsec = t.time_us;
  lt.angleX = std::atan((uPx - k.cx) / k.fx);
  lt.angleY = std::atan((vPx - k.cy) / k.fy);
  lt.sizeX = 2.f * std::atan(0.5f * static_cast<float>(t.box_px[2]) / k.fx);
  lt.sizeY = 2.f * std::atan(0.5f * static_cast<float>(t.box_px[3]) / k.fy);
  const float camM[3] = {static_cast<float>(t.centre_mm[0]) / 1000.f,
                         static_cast<float>(t.centre_mm[1]) / 1000.f,
                         static_cast<float>(t.centre_mm[2]) / 1000.f};
  float bodyM[3];
  cameraToBodyFrd(_config.mount, camM, bodyM);
  lt.x = bodyM[0];
  lt.y = bodyM[1];
  lt.z = bodyM[2];
  lt.distance = std::sqrt(bodyM[0] * bodyM[0] + bodyM[1] * bodyM[1] + bodyM[2] * bodyM[2]);
  lt.frame = kMavFrameBodyFrd;
  lt.type = kLandingTargetTypeVisionOther;
  lt.positionValid = _config.landingPosition ? 1 : 0;
  uint8_t p[64];
  transmit(kMsgLandingTarget, p, pack(lt, p));
}

}  // namespace cuetrack::platform::mavlink
