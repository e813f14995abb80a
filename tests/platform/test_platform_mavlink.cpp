// Our MAVLink 2 code on its own (the official library's view is test_platform_mavlink_official):
// CRC, framing, truncation, the parser's resync, payload layouts, the camera mount, and
// MavlinkLink's behaviour over an in-memory cable with a fake clock.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "cuetrack/platform/fake/FakeClock.hpp"
#include "cuetrack/platform/fake/FakeSerial.hpp"
#include "cuetrack/platform/fake/MemoryReporter.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"
#include "cuetrack/platform/mavlink/Sha256.hpp"

using namespace cuetrack;
using namespace cuetrack::platform;
using namespace cuetrack::platform::mavlink;

namespace {

std::vector<uint8_t> frameOf(uint32_t msgId, const uint8_t* payload, size_t len, uint8_t seq = 7) {
  Header h;
  h.seq = seq;
  h.sysId = 255;
  h.compId = 190;
  h.msgId = msgId;
  std::vector<uint8_t> out(kMaxFrameBytes);
  out.resize(encodeFrame(h, payload, len, out.data(), out.size()));
  return out;
}

std::vector<Message> parseAll(const std::vector<uint8_t>& bytes, Parser& p) {
  std::vector<Message> out;
  Message m;
  for (uint8_t b : bytes)
    if (p.push(b, &m)) out.push_back(m);
  return out;
}

std::vector<uint8_t> commandFrame(uint16_t command, std::initializer_list<float> params,
                                  uint8_t targetSys = 1, uint8_t targetComp = 100) {
  CommandLong c;
  int i = 0;
  for (float v : params) c.param[i++] = v;
  c.command = command;
  c.targetSystem = targetSys;
  c.targetComponent = targetComp;
  uint8_t p[40];
  return frameOf(kMsgCommandLong, p, pack(c, p));
}

}  // namespace

TEST_CASE("CRC-16/MCRF4XX: the catalogue's check value, and CRC_EXTRA per message") {
  const uint8_t digits[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  CHECK(crc16(digits, sizeof digits) == 0x6F91);
  REQUIRE(messageInfo(kMsgHeartbeat) != nullptr);
  CHECK(messageInfo(kMsgHeartbeat)->crcExtra == 50);
  CHECK(messageInfo(kMsgCameraTrackingImageStatus)->crcExtra == 126);
  CHECK(messageInfo(kMsgLandingTarget)->payloadBytes == 60);
  CHECK(messageInfo(12345) == nullptr);
}

TEST_CASE("a HEARTBEAT frame byte for byte (the worked example of docs/mavlink.md)") {
  Heartbeat h;
  h.type = kMavTypeCamera;
  h.autopilot = kMavAutopilotInvalid;
  h.systemStatus = kMavStateActive;
  h.customMode = 1;
  uint8_t p[16];
  Header hd;
  hd.seq = 0;
  hd.sysId = 1;
  hd.compId = 100;
  hd.msgId = kMsgHeartbeat;
  uint8_t w[32];
  const size_t n = encodeFrame(hd, p, pack(h, p), w, sizeof w);
  REQUIRE(n == 21);
  const uint8_t head[] = {0xFD, 9, 0, 0, 0, 1, 100, 0, 0, 0, 1, 0, 0, 0, 30, 8, 0, 4, 3};
  CHECK(std::memcmp(w, head, sizeof head) == 0);
  // The CRC over bytes 1..18 and CRC_EXTRA 50, little-endian.
  const uint16_t crc = crcAccumulate(50, crc16(w + 1, 18));
  CHECK(w[19] == (crc & 0xFF));
  CHECK(w[20] == (crc >> 8));
  CHECK(w[19] == 0x46);  // as docs/mavlink.md shows it
  CHECK(w[20] == 0xA4);
}

TEST_CASE("trailing zeros are cut from the payload and read back as zeros") {
  CommandAck a;
  a.command = kCmdCameraStopTracking;
  a.result = kResultAccepted;  // 0: everything after the command is zero
  uint8_t p[16];
  const auto w = frameOf(kMsgCommandAck, p, pack(a, p));
  CHECK(w[1] == 2);  // only the command's two bytes
  Parser parser;
  const auto got = parseAll(w, parser);
  REQUIRE(got.size() == 1);
  CHECK(got[0].len == 2);
  const CommandAck back = unpackCommandAck(got[0].payload);
  CHECK(back.command == kCmdCameraStopTracking);
  CHECK(back.targetSystem == 0);
  // An all-zero payload keeps one byte.
  const uint8_t zeros[9] = {};
  CHECK(frameOf(kMsgHeartbeat, zeros, 9)[1] == 1);
}

TEST_CASE("every message round-trips through our encoder and parser, field by field") {
  LandingTarget lt;
  lt.timeUsec = 0x0102030405060708ull;
  lt.angleX = -0.25f;
  lt.angleY = 0.125f;
  lt.distance = 2.5f;
  lt.x = 2.f;
  lt.y = -0.5f;
  lt.z = 0.25f;
  lt.frame = kMavFrameBodyFrd;
  lt.type = kLandingTargetTypeVisionOther;
  lt.positionValid = 1;
  uint8_t p[240];
  auto w = frameOf(kMsgLandingTarget, p, pack(lt, p));
  CameraTrackingImageStatus s;
  s.recTopX = 0.25f;
  s.recBottomY = 0.75f;
  s.trackingStatus = kTrackingStatusActive;
  s.trackingMode = kTrackingModeRectangle;
  const auto w2 = frameOf(kMsgCameraTrackingImageStatus, p, pack(s, p), 8);
  w.insert(w.end(), w2.begin(), w2.end());
  Parser parser;
  const auto got = parseAll(w, parser);
  REQUIRE(got.size() == 2);
  CHECK(got[0].header.sysId == 255);
  CHECK(got[0].header.compId == 190);
  CHECK(got[1].header.seq == 8);
  const LandingTarget b = unpackLandingTarget(got[0].payload);
  CHECK(b.timeUsec == lt.timeUsec);
  CHECK(b.angleX == lt.angleX);
  CHECK(b.distance == lt.distance);
  CHECK(b.y == lt.y);
  CHECK(b.q[0] == 1.f);
  CHECK(b.frame == kMavFrameBodyFrd);
  CHECK(b.positionValid == 1);
  const CameraTrackingImageStatus bs = unpackCameraTrackingImageStatus(got[1].payload);
  CHECK(bs.recTopX == 0.25f);
  CHECK(bs.recBottomY == 0.75f);
  CHECK(bs.trackingMode == kTrackingModeRectangle);
  // Little-endian on every host: the float 2.5 (0x40200000) at offset 16.
  CHECK(w[kHeaderBytes + 16] == 0x00);
  CHECK(w[kHeaderBytes + 19] == 0x40);
}

TEST_CASE("the parser counts bad frames, skips noise and others' messages, and resyncs") {
  const auto good = commandFrame(kCmdCameraStopTracking, {0});
  std::vector<uint8_t> stream = {0x00, 0x13, 0xFE, 0x09};  // noise, a MAVLink 1 start
  // A false start byte with a length that would swallow the good frame after it.
  stream.push_back(kStx);
  stream.push_back(200);
  stream.insert(stream.end(), good.begin(), good.end());
  auto corrupt = good;
  corrupt[kHeaderBytes + 3] ^= 0x10;  // CRC now wrong
  stream.insert(stream.end(), corrupt.begin(), corrupt.end());
  auto flagged = good;
  flagged[2] = 0x80;  // an incompat flag we do not know
  stream.insert(stream.end(), flagged.begin(), flagged.end());
  const uint8_t other[] = {1, 2, 3};
  Header h;
  h.msgId = 30;  // ATTITUDE: someone else's, CRC_EXTRA unknown to us
  uint8_t frame[64];
  // Hand-framed (our encoder refuses ids it does not know).
  frame[0] = kStx;
  frame[1] = 3;
  frame[2] = frame[3] = frame[4] = 0;
  frame[5] = 1;
  frame[6] = 1;
  frame[7] = 30;
  frame[8] = frame[9] = 0;
  std::memcpy(frame + 10, other, 3);
  frame[13] = frame[14] = 0xAA;
  stream.insert(stream.end(), frame, frame + 15);
  stream.insert(stream.end(), good.begin(), good.end());
  Parser parser;
  const auto got = parseAll(stream, parser);
  CHECK(got.size() == 2);  // the good frame after the false start, and the last one
  CHECK(parser.stats().messages == 2);
  CHECK(parser.stats().badCrc() == 1);  // the corrupt copy
  // The noise and the false start (0xFD as flags) in one run, the unknown flag.
  CHECK(parser.stats().badUnknown() == 2);
  CHECK(parser.stats().badLength() == 0);
  CHECK(parser.stats().ignored == 1);
  // Every byte is in a message, the ignored frame, or counted as discarded.
  const ParserStats& s = parser.stats();
  CHECK(s.discardedBytes[0] + s.discardedBytes[1] + s.discardedBytes[2] + 2 * good.size() + 15 ==
        stream.size());
}

TEST_CASE("a signed frame is read (its signature skipped)") {
  auto w = commandFrame(kCmdCameraStopTracking, {0});
  w[2] = kIncompatSigned;
  // The CRC does not cover the flags' meaning but does cover the byte: recompute it.
  uint16_t crc = crcAccumulate(messageInfo(kMsgCommandLong)->crcExtra,
                               crc16(w.data() + 1, kHeaderBytes - 1 + w[1]));
  w[kHeaderBytes + w[1]] = static_cast<uint8_t>(crc);
  w[kHeaderBytes + w[1] + 1] = static_cast<uint8_t>(crc >> 8);
  for (size_t i = 0; i < kSignatureBytes; ++i) w.push_back(static_cast<uint8_t>(i));
  Parser parser;
  CHECK(parseAll(w, parser).size() == 1);
  CHECK(parser.stats().totalErrors() == 0);
}

TEST_CASE("SHA-256: the FIPS 180-4 examples, whole and in pieces") {
  auto hex = [](const std::string& text, size_t piece) {
    Sha256 sha;
    const auto* p = reinterpret_cast<const uint8_t*>(text.data());
    for (size_t at = 0; at < text.size(); at += piece)
      sha.update(p + at, std::min(piece, text.size() - at));
    uint8_t d[32];
    sha.final(d);
    char out[65];
    for (int i = 0; i < 32; ++i) std::snprintf(out + 2 * i, 3, "%02x", d[i]);
    return std::string(out);
  };
  CHECK(hex("", 1) == "e3b0c44298fc1c149afbf4c8996fb92427ae41e4649b934ca495991b7852b855");
  CHECK(hex("abc", 1) == "ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad");
  const std::string two = "abcdbcdecdefdefgefghfghighijhijkijkljklmklmnlmnomnopnopq";  // 2 blocks
  for (size_t piece : {1u, 7u, 64u, 100u})
    CHECK(hex(two, piece) == "248d6a61d20638b8e5c026930c3e6039a33ce45964ff2167f6ecedd419db06c1");
}

TEST_CASE("signing: our signed frame checks with the key, not without; replays refused") {
  SigningKey key;
  for (int i = 0; i < 32; ++i) key.bytes[i] = static_cast<uint8_t>(i);
  CommandLong c;
  c.command = kCmdCameraStopTracking;
  c.targetSystem = 1;
  c.targetComponent = 100;
  uint8_t p[40];
  const size_t len = pack(c, p);
  Header h;
  h.sysId = 255;
  h.compId = 190;
  h.msgId = kMsgCommandLong;
  uint8_t w[kMaxFrameBytes];
  const size_t n = encodeSignedFrame(h, p, len, key, 2, 123456789, w, sizeof w);
  REQUIRE(n == kHeaderBytes + w[1] + kCrcBytes + kSignatureBytes);
  Parser parser;
  auto parse = [&](const uint8_t* f, size_t k) {
    size_t at = 0;
    Message m;
    REQUIRE(parser.nextInDatagram(f, k, &at, &m));
    return m;
  };
  SignatureChecker checker(key);
  CHECK(checker.check(parse(w, n), 0) == SignatureCheck::Good);
  CHECK(checker.check(parse(w, n), 0) == SignatureCheck::Replayed);
  SigningKey other;
  SignatureChecker stranger(other);
  CHECK(stranger.check(parse(w, n), 0) == SignatureCheck::BadSignature);
  uint8_t plain[kMaxFrameBytes];
  const size_t k = encodeFrame(h, p, len, plain, sizeof plain);
  CHECK(checker.check(parse(plain, k), 0) == SignatureCheck::Unsigned);
  // A new stream a minute older than the newest timestamp known: refused.
  SignatureChecker fresh(key);
  fresh.noteTimestamp(123456789 + kSigningNewStreamSlack + 1);
  CHECK(fresh.check(parse(w, n), 0) == SignatureCheck::TooOld);
}

TEST_CASE("camera mount: forward by default, pitch -90 looks down, offset added") {
  const float ahead[3] = {0.1f, 0.2f, 3.f};  // right, down, forward [m]
  float b[3];
  cameraToBodyFrd(CameraMount{}, ahead, b);
  CHECK(b[0] == Approx(3.f));
  CHECK(b[1] == Approx(0.1f));
  CHECK(b[2] == Approx(0.2f));
  CameraMount down;
  down.pitchDeg = -90.f;
  down.offsetM[0] = 0.1f;
  cameraToBodyFrd(down, ahead, b);
  CHECK(b[2] == Approx(3.f));           // the optical axis points down
  CHECK(b[0] == Approx(-0.2f + 0.1f));  // image down is towards the tail
  CHECK(b[1] == Approx(0.1f));
  CameraMount right;
  right.yawDeg = 90.f;
  cameraToBodyFrd(right, ahead, b);
  CHECK(b[1] == Approx(3.f));  // looking right
  CHECK(b[0] == Approx(-0.1f).margin(1e-6));
}

namespace {

struct Control final : LinkControl {
  std::vector<StartRequest> starts;
  int resets = 0, stops = 0;
  void requestStart(const StartRequest& r) override { starts.push_back(r); }
  void requestReset() override { ++resets; }
  void requestStop() override { ++stops; }
};

struct LinkRig {
  FakeClock clock{5000};
  FakeSerialCable cable;
  MemoryReporter reporter;
  MavlinkLink link{cable.a(), clock, reporter, LinkConfig{}};
  Control control;
  Parser host;
  LinkStatus status;
  std::vector<Message> got;
  void poll() { link.poll(control, status); }
  void send(const std::vector<uint8_t>& w) {
    REQUIRE(cable.b().write(w.data(), w.size()).bytes == w.size());
  }
  std::vector<Message> read() {
    std::vector<Message> out;
    uint8_t buf[512];
    for (;;) {
      const IoResult r = cable.b().read(buf, sizeof buf, 0);
      if (r.bytes == 0) break;
      Message m;
      for (size_t i = 0; i < r.bytes; ++i)
        if (host.push(buf[i], &m)) out.push_back(m);
    }
    got.insert(got.end(), out.begin(), out.end());
    return out;
  }
  std::vector<CommandAck> acks(const std::vector<Message>& ms) {
    std::vector<CommandAck> out;
    for (const Message& m : ms)
      if (m.header.msgId == kMsgCommandAck) out.push_back(unpackCommandAck(m.payload));
    return out;
  }
  FrameReport frame(uint8_t state, uint64_t timeUs) {
    FrameReport r;
    r.track.state = state;
    r.track.time_us = timeUs;
    r.track.box_px[0] = 300;
    r.track.box_px[1] = 200;
    r.track.box_px[2] = 40;
    r.track.box_px[3] = 80;
    r.track.flags = CTP_FLAG_HAS_3D;
    r.track.centre_mm[0] = 100;
    r.track.centre_mm[1] = -50;
    r.track.centre_mm[2] = 2000;
    r.widthPx = 640;
    r.heightPx = 480;
    r.intrinsics = kKinectV1Intrinsics;
    return r;
  }
};

int count(const std::vector<Message>& ms, uint32_t id) {
  int n = 0;
  for (const Message& m : ms) n += m.header.msgId == id;
  return n;
}

}  // namespace

TEST_CASE("MavlinkLink: a heartbeat at once and then once a second by the clock, seq counting up") {
  static LinkRig rig;
  rig.poll();
  auto ms = rig.read();
  REQUIRE(count(ms, kMsgHeartbeat) == 1);
  const Heartbeat h = unpackHeartbeat(ms[0].payload);
  CHECK(h.type == kMavTypeCamera);
  CHECK(h.autopilot == kMavAutopilotInvalid);
  CHECK(h.systemStatus == kMavStateStandby);
  CHECK(ms[0].header.sysId == 1);
  CHECK(ms[0].header.compId == 100);
  rig.clock.advanceUs(999999);
  rig.poll();
  CHECK(rig.read().empty());
  rig.clock.advanceUs(1);
  rig.status.state = CTP_STATE_TRACKING;
  rig.poll();
  ms = rig.read();
  REQUIRE(ms.size() == 1);
  CHECK(unpackHeartbeat(ms[0].payload).systemStatus == kMavStateActive);
  CHECK(ms[0].header.seq == 1);
  rig.status.noCamera = true;
  rig.clock.advanceUs(1000000);
  rig.poll();
  ms = rig.read();
  REQUIRE(ms.size() == 1);
  CHECK(unpackHeartbeat(ms[0].payload).systemStatus == kMavStateBoot);
  CHECK((unpackHeartbeat(ms[0].payload).customMode & 0x100u) != 0);
}

TEST_CASE("MavlinkLink: per-frame status and landing target, with the box and angles") {
  static LinkRig rig;
  rig.link.sendFrame(rig.frame(CTP_STATE_IDLE, 0));
  auto ms = rig.read();
  REQUIRE(ms.size() == 1);
  CameraTrackingImageStatus s = unpackCameraTrackingImageStatus(ms[0].payload);
  CHECK(s.trackingStatus == kTrackingStatusIdle);
  CHECK(std::isnan(s.recTopX));
  rig.link.sendFrame(rig.frame(CTP_STATE_TRACKING, 33333));
  ms = rig.read();
  REQUIRE(ms.size() == 2);
  REQUIRE(ms[0].header.msgId == kMsgCameraTrackingImageStatus);
  s = unpackCameraTrackingImageStatus(ms[0].payload);
  CHECK(s.trackingStatus == kTrackingStatusActive);
  CHECK(s.recTopX == Approx(300.f / 640));
  CHECK(s.recBottomY == Approx(280.f / 480));
  REQUIRE(ms[1].header.msgId == kMsgLandingTarget);
  const LandingTarget lt = unpackLandingTarget(ms[1].payload);
  CHECK(lt.timeUsec == 33333);
  CHECK(lt.angleX == Approx(std::atan((320.f - 325.5f) / 518.f)));
  CHECK(lt.angleY == Approx(std::atan((240.f - 253.5f) / 519.f)));
  CHECK(lt.x == Approx(2.f));
  CHECK(lt.y == Approx(0.1f));
  CHECK(lt.z == Approx(-0.05f));
  CHECK(lt.distance == Approx(std::sqrt(4.f + 0.01f + 0.0025f)));
  CHECK(lt.frame == kMavFrameBodyFrd);
  // For PX4: angles and distance only.
  LinkConfig px4;
  px4.landingPosition = false;
  FakeSerialCable cable;
  MavlinkLink anglesOnly(cable.a(), rig.clock, rig.reporter, px4);
  anglesOnly.sendFrame(rig.frame(CTP_STATE_TRACKING, 50000));
  uint8_t buf[256];
  const IoResult r = cable.b().read(buf, sizeof buf, 0);
  Parser parser;
  const auto px4Msgs = parseAll(std::vector<uint8_t>(buf, buf + r.bytes), parser);
  REQUIRE(px4Msgs.size() == 2);
  CHECK(unpackLandingTarget(px4Msgs[1].payload).positionValid == 0);
  CHECK(unpackLandingTarget(px4Msgs[1].payload).angleX == Approx(lt.angleX));
  // Lost: a status saying so, no landing target.
  rig.link.sendFrame(rig.frame(CTP_STATE_LOST, 66666));
  ms = rig.read();
  REQUIRE(ms.size() == 1);
  CHECK(unpackCameraTrackingImageStatus(ms[0].payload).trackingStatus == kTrackingStatusError);
}

TEST_CASE("MavlinkLink: track commands are acknowledged once, after the tracker's answer") {
  static LinkRig rig;
  rig.send(commandFrame(kCmdCameraTrackRectangle, {0.25f, 0.25f, 0.5f, 0.75f}));
  rig.poll();
  REQUIRE(rig.control.starts.size() == 1);
  const StartRequest r = rig.control.starts[0];
  CHECK(r.kind == StartRequest::Kind::BoxNormalised);
  CHECK(r.box.w == Approx(0.25f));
  CHECK(r.box.h == Approx(0.5f));
  CHECK(rig.acks(rig.read()).empty());  // not yet
  rig.link.answerStart(r.token, StartOutcome::Started);
  rig.link.answerStart(r.token, StartOutcome::Started);  // a second answer sends nothing
  auto acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 1);
  CHECK(acks[0].command == kCmdCameraTrackRectangle);
  CHECK(acks[0].result == kResultAccepted);
  CHECK(acks[0].targetSystem == 255);
  CHECK(acks[0].targetComponent == 190);

  // A point, then a rectangle before the point was tried: the point is cancelled.
  rig.send(commandFrame(kCmdCameraTrackPoint, {0.5f, 0.5f, 0.f}));
  rig.poll();
  REQUIRE(rig.control.starts.size() == 2);
  CHECK(rig.control.starts[1].kind == StartRequest::Kind::PointNormalised);
  rig.send(commandFrame(kCmdCameraTrackRectangle, {0.1f, 0.1f, 0.2f, 0.2f}));
  rig.poll();
  rig.link.answerStart(rig.control.starts[1].token, StartOutcome::Superseded);
  rig.link.answerStart(rig.control.starts[2].token, StartOutcome::Refused);
  acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 2);
  CHECK(acks[0].command == kCmdCameraTrackPoint);
  CHECK(acks[0].result == kResultCancelled);
  CHECK(acks[1].result == kResultDenied);

  // Bad parameters are denied at once; stop resets; unknown commands are unsupported.
  rig.send(commandFrame(kCmdCameraTrackRectangle, {0.5f, 0.5f, 0.4f, 0.9f}));
  rig.send(commandFrame(kCmdCameraTrackPoint, {NAN, 0.5f, 0.f}));
  rig.send(commandFrame(kCmdCameraTrackRectangle, {0.1f, 0.1f, 0.2f, 0.2f, 42.f}));  // camera 42
  rig.send(commandFrame(kCmdCameraStopTracking, {NAN}));  // NaN: camera id not given
  rig.send(commandFrame(400, {1}));                       // ARM_DISARM
  rig.poll();
  acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 5);
  CHECK(acks[0].result == kResultDenied);
  CHECK(acks[1].result == kResultDenied);
  CHECK(acks[2].result == kResultDenied);
  CHECK(acks[3].result == kResultAccepted);
  CHECK(acks[4].result == kResultUnsupported);
  CHECK(rig.control.starts.size() == 3);
  CHECK(rig.control.resets == 1);

  // Commands for another system or component get no answer from us.
  rig.send(commandFrame(kCmdCameraStopTracking, {0}, 2, 100));
  rig.send(commandFrame(kCmdCameraStopTracking, {0}, 1, 1));
  rig.poll();
  CHECK(rig.acks(rig.read()).empty());
  CHECK(rig.control.resets == 1);
}

TEST_CASE("MavlinkLink: only accepted senders are obeyed; strangers are refused and counted") {
  LinkConfig config;
  config.acceptSysIds[0] = 1;    // the autopilot
  config.acceptSysIds[1] = 255;  // the ground station
  config.acceptSysIdCount = 2;
  FakeClock clock{5000};
  FakeSerialCable cable;
  MemoryReporter reporter;
  static MavlinkLink link{cable.a(), clock, reporter, config};  // 64 KiB: static
  Control control;
  Parser host;
  auto sendFrom = [&](uint8_t sys, const std::vector<uint8_t>& frame) {
    auto w = frame;
    w[5] = sys;  // the sender's system id, then the CRC again
    const uint16_t crc = crcAccumulate(messageInfo(kMsgCommandLong)->crcExtra,
                                       crc16(w.data() + 1, kHeaderBytes - 1 + w[1]));
    w[kHeaderBytes + w[1]] = static_cast<uint8_t>(crc);
    w[kHeaderBytes + w[1] + 1] = static_cast<uint8_t>(crc >> 8);
    REQUIRE(cable.b().write(w.data(), w.size()).bytes == w.size());
  };
  auto acks = [&] {
    std::vector<CommandAck> out;
    uint8_t buf[512];
    for (IoResult r; (r = cable.b().read(buf, sizeof buf, 0)).bytes > 0;) {
      Message m;
      for (size_t i = 0; i < r.bytes; ++i)
        if (host.push(buf[i], &m) && m.header.msgId == kMsgCommandAck)
          out.push_back(unpackCommandAck(m.payload));
    }
    return out;
  };
  const auto track = commandFrame(kCmdCameraTrackRectangle, {0.1f, 0.1f, 0.2f, 0.2f});
  const auto stop = commandFrame(kCmdCameraStopTracking, {0});
  sendFrom(7, track);  // a stranger on the network
  sendFrom(7, stop);
  link.poll(control, LinkStatus{});
  CHECK(acks().empty());  // no answer: it learns nothing
  CHECK(control.starts.empty());
  CHECK(control.resets == 0);
  CHECK(link.stats().rxRefused == 2);
  sendFrom(255, stop);  // the ground station
  sendFrom(1, stop);    // the autopilot
  link.poll(control, LinkStatus{});
  const auto got = acks();
  REQUIRE(got.size() == 2);
  CHECK(got[0].result == kResultAccepted);
  CHECK(control.resets == 2);
  CHECK(link.stats().rxRefused == 2);
}

TEST_CASE("MavlinkLink: broadcasts obeyed only where the camera protocol allows them") {
  static LinkRig rig;
  // Component 0 (every component of system 1), and system 0 (every system).
  rig.send(commandFrame(kCmdRequestMessage, {259}, 1, 0));      // discovery: answered
  rig.send(commandFrame(kCmdCameraStopTracking, {0}, 0, 100));  // camera id 0: obeyed
  rig.send(commandFrame(kCmdCameraTrackRectangle, {0.1f, 0.1f, 0.2f, 0.2f, 0.f}, 1, 0));
  rig.poll();
  auto acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 2);  // the rectangle waits for the tracker
  CHECK(acks[0].command == kCmdRequestMessage);
  CHECK(acks[0].result == kResultAccepted);
  CHECK(acks[1].result == kResultAccepted);
  CHECK(rig.control.resets == 1);
  CHECK(rig.control.starts.size() == 1);
  rig.link.answerStart(rig.control.starts[0].token, StartOutcome::Started);
  rig.read();
  // A broadcast must name camera 0: NaN (not given) or our id is DENIED, as the camera
  // protocol says; a broadcast interval change is refused without an answer; someone
  // else's broadcast (an autopilot's mission camera command) is not ours at all.
  rig.send(commandFrame(kCmdCameraStopTracking, {NAN}, 1, 0));
  rig.send(commandFrame(kCmdCameraTrackPoint, {0.5f, 0.5f, 0.f, 100.f}, 1, 0));
  rig.send(commandFrame(kCmdSetMessageInterval, {275, 1000000}, 1, 0));
  rig.send(commandFrame(2000, {0, 1, 0}, 1, 0));  // IMAGE_START_CAPTURE
  rig.poll();
  acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 2);
  CHECK(acks[0].command == kCmdCameraStopTracking);
  CHECK(acks[0].result == kResultDenied);
  CHECK(acks[1].command == kCmdCameraTrackPoint);
  CHECK(acks[1].result == kResultDenied);
  CHECK(rig.control.resets == 1);
  CHECK(rig.control.starts.size() == 1);
  CHECK(rig.link.stats().rxRefused == 3);
}

TEST_CASE("MavlinkLink: CAMERA_INFORMATION on request, message intervals, bad bytes counted") {
  static LinkRig rig;
  rig.link.sendFrame(rig.frame(CTP_STATE_IDLE, 0));
  rig.read();
  rig.send(commandFrame(kCmdRequestMessage, {static_cast<float>(kMsgCameraInformation)}));
  rig.send(commandFrame(kCmdRequestMessage, {33.f}));  // GLOBAL_POSITION_INT: not ours
  rig.poll();
  auto ms = rig.read();
  std::vector<uint32_t> ids;
  for (const Message& m : ms)
    if (m.header.msgId != kMsgHeartbeat) ids.push_back(m.header.msgId);
  REQUIRE(ids == std::vector<uint32_t>{kMsgCommandAck, kMsgCameraInformation, kMsgCommandAck});
  for (const Message& m : ms) {
    if (m.header.msgId != kMsgCameraInformation) continue;
    uint32_t flags = 0;
    for (int i = 3; i >= 0; --i) flags = (flags << 8) | m.payload[20 + i];
    CHECK(flags == (kCameraCapHasTrackingPoint | kCameraCapHasTrackingRectangle));
    CHECK((m.payload[24] | m.payload[25] << 8) == 640);
  }
  CHECK(rig.acks(ms)[1].result == kResultDenied);

  // Status every 100 ms at 30 fps: every 3rd frame; -1 turns it off.
  rig.send(commandFrame(kCmdSetMessageInterval,
                        {static_cast<float>(kMsgCameraTrackingImageStatus), 100000.f}));
  rig.poll();
  REQUIRE(rig.acks(rig.read())[0].result == kResultAccepted);
  for (int f = 0; f < 9; ++f) rig.link.sendFrame(rig.frame(CTP_STATE_IDLE, 33333u * f));
  CHECK(count(rig.read(), kMsgCameraTrackingImageStatus) == 3);
  rig.send(commandFrame(kCmdSetMessageInterval,
                        {static_cast<float>(kMsgCameraTrackingImageStatus), -1.f}));
  rig.send(commandFrame(kCmdSetMessageInterval, {0.f, 1000.f}));  // HEARTBEAT: fixed at 1 Hz
  rig.poll();
  const auto acks = rig.acks(rig.read());
  REQUIRE(acks.size() == 2);
  CHECK(acks[1].result == kResultDenied);
  for (int f = 9; f < 12; ++f) rig.link.sendFrame(rig.frame(CTP_STATE_IDLE, 33333u * f));
  CHECK(count(rig.read(), kMsgCameraTrackingImageStatus) == 0);

  // Garbage and a corrupted command: counted, not applied, the link goes on.
  auto bad = commandFrame(kCmdCameraStopTracking, {0});
  bad[12] ^= 0x01;
  std::vector<uint8_t> junk = {kStx, 5, 0x40, 1, 2, 3};
  junk.insert(junk.end(), bad.begin(), bad.end());
  rig.send(junk);
  rig.poll();
  CHECK(rig.link.stats().rxErrors >= 2);
  CHECK(rig.control.resets == 0);
  rig.send(commandFrame(kCmdCameraStopTracking, {0}));
  rig.poll();
  CHECK(rig.control.resets == 1);
}

TEST_CASE("MavlinkLink: a peer that stops reading never blocks; drops are counted and seq skips") {
  static LinkRig rig;
  rig.cable.setCapacityAtoB(100);
  for (int f = 0; f < 50; ++f) rig.link.sendFrame(rig.frame(CTP_STATE_TRACKING, 33333u * f));
  const LinkStats& s = rig.link.stats();
  CHECK(s.txDropped > 0);
  CHECK(s.sent + s.txDropped + s.queued == 100);  // status + landing target per frame
  rig.cable.setCapacityAtoB(FakeSerialCable::kRingBytes);
  rig.link.drain(10);
  rig.read();
  rig.clock.advanceUs(1000000);  // the output budget refilled
  rig.link.sendFrame(rig.frame(CTP_STATE_IDLE, 33333u * 50));
  const auto ms = rig.read();
  REQUIRE(ms.size() == 1);
  CHECK(ms[0].header.seq == 100);  // every message took a seq, sent or not
}

namespace {

// A signed STOP_TRACKING from the ground station (255/190, link 1) with this timestamp.
std::vector<uint8_t> signedStop(const SigningKey& key, uint64_t timestamp) {
  CommandLong c;
  c.command = kCmdCameraStopTracking;
  c.targetSystem = 1;
  c.targetComponent = 100;
  uint8_t p[40];
  Header h;
  h.sysId = 255;
  h.compId = 190;
  h.msgId = kMsgCommandLong;
  std::vector<uint8_t> w(kMaxFrameBytes);
  w.resize(encodeSignedFrame(h, p, pack(c, p), key, 1, timestamp, w.data(), w.size()));
  return w;
}

uint64_t timestampOf(const Message& m) {
  uint64_t t = 0;
  for (int i = 0; i < 6; ++i) t |= static_cast<uint64_t>(m.signature[1 + i]) << (8 * i);
  return t;
}

// A signing link whose clock reads `clock` (signing units; 0: not set) at start.
struct SignedRig {
  FakeClock clock{5000};
  FakeSerialCable cable;
  MemoryReporter reporter;
  SigningKey key;
  std::unique_ptr<MavlinkLink> link;
  Control control;
  Parser host;
  std::vector<uint64_t> sentTimestamps;  // of every frame the link sent, in order
  explicit SignedRig(uint64_t clockTimestamp) {
    for (int i = 0; i < 32; ++i) key.bytes[i] = static_cast<uint8_t>(3 * i + 1);
    LinkConfig c;
    c.signing = true;
    c.key = key;
    c.signingTimestamp = clockTimestamp;
    link = std::make_unique<MavlinkLink>(cable.a(), clock, reporter, c);
  }
  // Polls with `in` waiting (if any); the ACKs the link answered.
  int exchange(const std::vector<uint8_t>& in) {
    if (!in.empty()) REQUIRE(cable.b().write(in.data(), in.size()).bytes == in.size());
    link->poll(control, LinkStatus{});
    int acks = 0;
    uint8_t buf[512];
    for (IoResult r; (r = cable.b().read(buf, sizeof buf, 0)).bytes > 0;)
      for (size_t i = 0; i < r.bytes; ++i) {
        Message m;
        if (!host.push(buf[i], &m)) continue;
        sentTimestamps.push_back(timestampOf(m));
        acks += m.header.msgId == kMsgCommandAck;
      }
    return acks;
  }
  bool increasing() const {
    for (size_t i = 1; i < sentTimestamps.size(); ++i)
      if (sentTimestamps[i] <= sentTimestamps[i - 1]) return false;
    return true;
  }
};

}  // namespace

TEST_CASE(
    "signing: a timestamp a minute ahead of our clock is refused, not adopted (issue 56, 3)") {
  constexpr uint64_t kNow = 300000000000ull;  // about 2016
  SignedRig rig(kNow);
  rig.exchange({});  // the first heartbeat
  // One correctly signed command at 2^48 - 3: refused and counted; our clock stays ours.
  CHECK(rig.exchange(signedStop(rig.key, kSigningMaxTimestamp - 2)) == 0);
  CHECK(rig.link->stats().rxRefused == 1);
  rig.clock.advanceUs(1000000);
  rig.exchange({});  // the next heartbeat
  // 30 s ahead: within the minute, obeyed; two minutes ahead: refused.
  CHECK(rig.exchange(signedStop(rig.key, kNow + 100000 + 3000000)) == 1);
  CHECK(rig.exchange(signedStop(rig.key, kNow + 100000 + 12000000)) == 0);
  CHECK(rig.link->stats().rxRefused == 2);
  REQUIRE(rig.sentTimestamps.size() >= 3);
  CHECK(rig.increasing());
  // Never dragged towards 2^48: at most what we believed (30 s ahead) and a few steps.
  CHECK(rig.sentTimestamps.back() < kNow + 100000 + 3000000 + 100);
}

TEST_CASE("signing on a board whose clock is not set: nothing after 2100 believed") {
  SignedRig rig(0);
  rig.exchange({});
  CHECK(rig.exchange(signedStop(rig.key, kSigningMaxTimestamp - 2)) == 0);
  constexpr uint64_t k2026 = 35000000000000ull;
  CHECK(rig.exchange(signedStop(rig.key, k2026)) == 1);             // believed: now our clock
  CHECK(rig.exchange(signedStop(rig.key, k2026 + 12000000)) == 0);  // 2 min ahead of it
  CHECK(rig.link->stats().rxRefused == 2);
  CHECK(rig.increasing());
  CHECK(rig.sentTimestamps.back() > k2026);
  CHECK(rig.sentTimestamps.back() < k2026 + 100);
}

TEST_CASE("signing: our timestamps never reach 2^48; what cannot be signed is dropped, counted") {
  SignedRig rig(kSigningMaxTimestamp - 2);  // a clock set absurdly late
  for (int i = 0; i < 5; ++i) {
    rig.exchange({});
    rig.link->sendFrame(FrameReport{});  // a status message each
  }
  rig.exchange({});
  CHECK(rig.sentTimestamps.size() == 3);  // max - 2, max - 1, max
  CHECK(rig.sentTimestamps.back() == kSigningMaxTimestamp);
  CHECK(rig.increasing());
  CHECK(rig.link->stats().txDropped == 3);
}

TEST_CASE("output paced to the link's rate: answers wait, telemetry without room is dropped") {
  FakeClock clock(5000);
  FakeSerialCable cable;
  MemoryReporter reporter;
  LinkConfig config;
  config.outputBytesPerS = 11520;  // 115200 baud
  MavlinkLink link(cable.a(), clock, reporter, config);
  Control control;
  std::vector<uint8_t> commands;
  for (int i = 0; i < 80; ++i) {
    const auto c = commandFrame(static_cast<uint16_t>(40000 + i), {});  // UNSUPPORTED
    commands.insert(commands.end(), c.begin(), c.end());
  }
  REQUIRE(cable.b().write(commands.data(), commands.size()).bytes == commands.size());
  Parser host;
  std::vector<uint16_t> answered;
  size_t mostBytesAfterFirst = 0, firstBytes = 0;
  int statusSent = 0;
  for (int frame = 0; frame < 30 && answered.size() < 80; ++frame) {
    link.poll(control, LinkStatus{});
    FrameReport r;
    r.widthPx = 640;
    r.heightPx = 480;
    r.track.time_us = 33333u * static_cast<uint64_t>(frame);
    link.sendFrame(r);  // a status a frame: dropped while answers wait
    uint8_t buf[4096];
    const IoResult got = cable.b().read(buf, sizeof buf, 0);
    (frame == 0 ? firstBytes : mostBytesAfterFirst) =
        std::max(frame == 0 ? firstBytes : mostBytesAfterFirst, got.bytes);
    for (size_t i = 0; i < got.bytes; ++i) {
      Message m;
      if (!host.push(buf[i], &m)) continue;
      if (m.header.msgId == kMsgCommandAck) answered.push_back(unpackCommandAck(m.payload).command);
      statusSent += m.header.msgId == kMsgCameraTrackingImageStatus;
    }
    clock.advanceUs(33333);
  }
  REQUIRE(answered.size() == 80);  // every answer, in order
  for (size_t i = 0; i < answered.size(); ++i) CHECK(answered[i] == 40000 + i);
  CHECK(firstBytes <= 11520 / 20 + kMaxFrameBytes);           // the burst: 50 ms of the rate
  CHECK(mostBytesAfterFirst <= 11520 / 30 + kMaxFrameBytes);  // then a frame's worth
  const LinkStats& s = link.stats();
  CHECK(s.txDropped > 0);  // the statuses that found answers waiting
  CHECK(s.sent == 80 + 1 + static_cast<uint32_t>(statusSent));  // ACKs, a heartbeat, statuses
}
