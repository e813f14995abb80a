// cuetrack --protocol mavlink end to end, the real binary over a socat pty, the other
// end played by the official MAVLink C library (../shared/tools/mavlink-c):
//   - it decodes 100 % of what cuetrack sends on a generated scene (no bad CRC, no seq
//     gap), the status box is the track's, the landing target's angles the intrinsics';
//   - the three tracking commands it frames start by rectangle, track, point, stop,
//     each answered by one COMMAND_ACK with the right MAV_RESULT;
//   - a peer that stops reading does not block the tracker; the drops are counted;
//   - --mavlink-udp to a loopback peer: the same, a datagram at a time.
// Skipped (reported as such) without socat or without the shared folder.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <netinet/in.h>
#include <poll.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "LoopbackUdp.hpp"
#include "Process.hpp"
#include "Skip.hpp"
#include "TempDir.hpp"
#include "TestPaths.hpp"
#include "TestPrograms.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#include "cuetrack/platform/linux/KeyFile.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack/platform/mavlink/MavlinkMessages.hpp"
#ifdef CUETRACK_HAVE_MAVLINK_C
#include "official/OfficialMavlink.hpp"
#endif

using namespace cuetrack;
using namespace cuetrack::test;
using namespace cuetrack::platform::mavlink;

#ifndef CUETRACK_HAVE_MAVLINK_C
TEST_CASE("cuetrack --protocol mavlink against the official library over a pty") {
  CUETRACK_SKIP("no " CUETRACK_SHARED_DIR "/tools/mavlink-c at configure time");
}
#else
namespace {

constexpr int kAppTimeoutMs = 120000;  // generous: 2 cores shared by many builds
constexpr uint8_t kGcsSys = 255, kGcsComp = 190;

std::vector<std::string> csvRows(const std::string& text) {
  std::vector<std::string> out;
  size_t start = text.find('\n');  // after the header
  while (start != std::string::npos && start + 1 < text.size()) {
    const size_t end = text.find('\n', start + 1);
    out.push_back(text.substr(start + 1, end - start - 1));
    start = end;
  }
  return out;
}

// seq,time_us,state,x,y,w,h,has3d,cx,cy,cz,...
struct Row {
  std::string state;
  int box[4];
  int has3d;
  int centreMm[3];
};
Row parseRow(const std::string& line) {
  Row r{};
  char state[32];
  unsigned long long t;
  unsigned seq;
  REQUIRE(std::sscanf(line.c_str(), "%u,%llu,%31[^,],%d,%d,%d,%d,%d,%d,%d,%d", &seq, &t, state,
                      &r.box[0], &r.box[1], &r.box[2], &r.box[3], &r.has3d, &r.centreMm[0],
                      &r.centreMm[1], &r.centreMm[2]) == 11);
  r.state = state;
  return r;
}

// The ground station's end, decoding with the official library.
struct Gcs {
  platform::SerialPort port;
  official::Decoder dec;
  std::vector<official::Decoded> got;
  int badCrc = 0;
  void readSome(int timeoutMs) {
    uint8_t buf[1024];
    const platform::IoResult r = port.read(buf, sizeof buf, timeoutMs);
    for (size_t i = 0; i < r.bytes; ++i) {
      official::Decoded d;
      const int res = dec.push(buf[i], &d);
      if (res == 1) got.push_back(d);
      badCrc += res < 0;
    }
  }
  // Reads until pred holds for a message received from now on (kept in `match`).
  template <typename P>
  bool until(P pred, int timeoutMs) {
    size_t from = got.size();
    return waitFor(
        [&] {
          readSome(10);
          for (; from < got.size(); ++from) {
            if (!pred(got[from])) continue;
            match = got[from];
            return true;
          }
          return false;
        },
        timeoutMs);
  }
  official::Decoded match;
  void command(uint16_t cmd, std::initializer_list<float> params) {
    float p[7] = {0, 0, 0, 0, 0, 0, 0};
    int i = 0;
    for (float v : params) p[i++] = v;
    uint8_t w[300];
    const size_t n = official::encodeCommandLong(kGcsSys, kGcsComp, 1, 100, cmd, p, w, sizeof w);
    REQUIRE(n > 0);
    REQUIRE(port.write(w, n).bytes == n);
  }
  int acks(uint16_t cmd, uint8_t result) const {
    int n = 0;
    for (const auto& d : got)
      n += d.msgId == kMsgCommandAck && d.ackCommand == cmd && d.ackResult == result;
    return n;
  }
};

bool ackOf(const official::Decoded& d, uint16_t cmd) {
  return d.msgId == kMsgCommandAck && d.ackCommand == cmd && d.ackTargetSystem == kGcsSys &&
         d.ackTargetComponent == kGcsComp;
}

bool status(const official::Decoded& d, uint8_t trackingStatus) {
  return d.msgId == kMsgCameraTrackingImageStatus && d.trackingStatus == trackingStatus;
}

CameraIntrinsics sceneIntrinsics() {
  SceneSpec spec;
  REQUIRE(makeScene("moving", &spec));
  static SyntheticSource synth(spec, 1);
  static FrameSlot slot;
  REQUIRE(synth.next(slot) == ReadStatus::Ok);
  return slot.intrinsics;
}

bool haveSocat() {
  return fileExists("/usr/bin/socat");
}

}  // namespace

TEST_CASE("the official library decodes 100 % of what cuetrack sends; box and angles as tracked") {
  if (!haveSocat()) CUETRACK_SKIP("socat not installed");
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  Gcs gcs;
  REQUIRE(gcs.port.open(pty.b(), 921600));
  const std::string csv = tmp / "app.csv", appErr = tmp / "app.err";
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--source", "synth:moving", "--serial", pty.a(),
                        "--baud",         "921600",   "--protocol",   "mavlink",  "--out",
                        csv.c_str(),      "--frames", "60",           "--quiet",  nullptr};
  REQUIRE(app.start(argv, nullptr, appErr.c_str()));
  auto statuses = [&] {
    int n = 0;
    for (const auto& d : gcs.got) n += d.msgId == kMsgCameraTrackingImageStatus;
    return n;
  };
  REQUIRE(waitFor(
      [&] {
        gcs.readSome(10);
        return statuses() >= 60;
      },
      kAppTimeoutMs));
  int exitStatus = -1;
  REQUIRE(app.wait(kAppTimeoutMs, &exitStatus));
  INFO(readText(appErr));
  REQUIRE(exitStatus == 0);
  gcs.readSome(50);

  CHECK(gcs.badCrc == 0);
  REQUIRE(gcs.got.size() > 60);
  for (size_t i = 1; i < gcs.got.size(); ++i) {  // no message lost on the way
    INFO("message " << i);
    CHECK(gcs.got[i].seq == static_cast<uint8_t>(gcs.got[i - 1].seq + 1));
  }
  const std::vector<std::string> rows = csvRows(readText(csv));
  REQUIRE(rows.size() == 60);
  const CameraIntrinsics k = sceneIntrinsics();
  size_t row = 0;
  int heartbeats = 0, landing = 0;
  for (const auto& d : gcs.got) {
    CHECK(d.sysId == 1);
    CHECK(d.compId == 100);
    if (d.msgId == kMsgHeartbeat) {
      ++heartbeats;
      CHECK(d.hbType == kMavTypeCamera);
      continue;
    }
    // A frame's status, then (in 3D) its landing target.
    const size_t frame = d.msgId == kMsgLandingTarget ? row - 1 : row;
    REQUIRE(frame < rows.size());
    const Row r = parseRow(rows[frame]);
    INFO("frame " << frame << ": " << rows[frame]);
    if (d.msgId == kMsgCameraTrackingImageStatus) {
      ++row;
      REQUIRE(r.state == "tracking");  // the scene's ground truth starts it
      CHECK(d.trackingStatus == kTrackingStatusActive);
      CHECK(d.recTopX * 640 == Approx(r.box[0]).margin(1e-3));
      CHECK(d.recTopY * 480 == Approx(r.box[1]).margin(1e-3));
      CHECK(d.recBottomX * 640 == Approx(r.box[0] + r.box[2]).margin(1e-3));
      CHECK(d.recBottomY * 480 == Approx(r.box[1] + r.box[3]).margin(1e-3));
    } else if (d.msgId == kMsgLandingTarget) {
      ++landing;
      REQUIRE(r.has3d == 1);
      const float u = r.box[0] + 0.5f * r.box[2], v = r.box[1] + 0.5f * r.box[3];
      CHECK(d.angleX == Approx(std::atan((u - k.cx) / k.fx)));
      CHECK(d.angleY == Approx(std::atan((v - k.cy) / k.fy)));
      // The default mount looks forward: x = depth, y = right, z = down.
      CHECK(d.x == Approx(r.centreMm[2] / 1000.f));
      CHECK(d.y == Approx(r.centreMm[0] / 1000.f));
      CHECK(d.z == Approx(r.centreMm[1] / 1000.f));
      CHECK(d.frame == kMavFrameBodyFrd);
    } else {
      FAIL("unexpected message " << d.msgId);
    }
  }
  CHECK(row == 60);
  // One per frame with a 3D position (not the first: the box as given, no depth yet).
  int with3d = 0;
  for (const std::string& line : rows) with3d += parseRow(line).has3d;
  CHECK(landing == with3d);
  CHECK(with3d >= 50);  // so that the angles above were checked on most frames
  CHECK(heartbeats >= 1);
}

TEST_CASE("commands framed by the official library: rectangle, track, point, stop; one ACK each") {
  if (!haveSocat()) CUETRACK_SKIP("socat not installed");
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  Gcs gcs;
  REQUIRE(gcs.port.open(pty.b(), 115200));
  const std::string appErr = tmp / "app.err";
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--serial", pty.a(),  "--protocol", "mavlink",
                        "--no-gt",        "--frames", "100000", "--quiet",    nullptr};
  REQUIRE(app.start(argv, nullptr, appErr.c_str()));
  INFO(readText(appErr));
  REQUIRE(gcs.until([](const official::Decoded& d) { return d.msgId == kMsgHeartbeat; }, 30000));
  REQUIRE(gcs.until([](const auto& d) { return status(d, kTrackingStatusIdle); }, 30000));

  // The scene's target near 280,240 40x60 px of 640x480.
  gcs.command(kCmdCameraTrackRectangle, {0.4375f, 0.5f, 0.5f, 0.625f});
  REQUIRE(gcs.until([](const auto& d) { return ackOf(d, kCmdCameraTrackRectangle); }, 30000));
  CHECK(gcs.match.ackResult == kResultAccepted);
  REQUIRE(gcs.until([](const auto& d) { return status(d, kTrackingStatusActive); }, 30000));
  CHECK(gcs.match.trackingMode == kTrackingModeRectangle);
  REQUIRE(gcs.until([](const auto& d) { return d.msgId == kMsgLandingTarget; }, 30000));

  gcs.command(kCmdRequestMessage, {static_cast<float>(kMsgCameraInformation)});
  REQUIRE(gcs.until([](const auto& d) { return d.msgId == kMsgCameraInformation; }, 30000));
  CHECK(gcs.match.camFlags == (kCameraCapHasTrackingPoint | kCameraCapHasTrackingRectangle));

  gcs.command(kCmdCameraTrackPoint, {0.4688f, 0.5625f, 0.f});
  REQUIRE(gcs.until([](const auto& d) { return ackOf(d, kCmdCameraTrackPoint); }, 30000));
  CHECK(gcs.match.ackResult == kResultAccepted);
  REQUIRE(gcs.until(
      [](const auto& d) {
        return status(d, kTrackingStatusActive) && d.trackingMode == kTrackingModePoint;
      },
      30000));

  gcs.command(kCmdCameraStopTracking, {0.f});
  REQUIRE(gcs.until([](const auto& d) { return ackOf(d, kCmdCameraStopTracking); }, 30000));
  CHECK(gcs.match.ackResult == kResultAccepted);
  REQUIRE(gcs.until([](const auto& d) { return status(d, kTrackingStatusIdle); }, 30000));

  // A rectangle upside down is denied; the tracker stays idle.
  gcs.command(kCmdCameraTrackRectangle, {0.5f, 0.6f, 0.4f, 0.5f});
  REQUIRE(gcs.until([](const auto& d) { return ackOf(d, kCmdCameraTrackRectangle); }, 30000));
  CHECK(gcs.match.ackResult == kResultDenied);
  REQUIRE(gcs.until([](const auto& d) { return status(d, kTrackingStatusIdle); }, 30000));

  // Acks come in order: by now every command has had its answer, and only one.
  CHECK(gcs.acks(kCmdCameraTrackRectangle, kResultAccepted) == 1);
  CHECK(gcs.acks(kCmdCameraTrackRectangle, kResultDenied) == 1);
  CHECK(gcs.acks(kCmdCameraTrackPoint, kResultAccepted) == 1);
  CHECK(gcs.acks(kCmdCameraStopTracking, kResultAccepted) == 1);
  CHECK(gcs.acks(kCmdRequestMessage, kResultAccepted) == 1);
  CHECK(gcs.badCrc == 0);
  app.signal(SIGTERM);
  int exitStatus = -1;
  REQUIRE(app.wait(30000, &exitStatus));
  CHECK(exitStatus == 0);
}

TEST_CASE("a MAVLink peer that stops reading does not block the tracker; drops are counted") {
  if (!haveSocat()) CUETRACK_SKIP("socat not installed");
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  platform::SerialPort stalled;  // opened, never read
  REQUIRE(stalled.open(pty.b(), 115200));
  const std::string csv = tmp / "app.csv", appErr = tmp / "app.err";
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--source",   "synth:moving", "--serial",
                        pty.a(),          "--protocol", "mavlink",      "--out",
                        csv.c_str(),      "--frames",   "600",          nullptr};
  REQUIRE(app.start(argv, nullptr, appErr.c_str()));
  int exitStatus = -1;
  // 600 frames: the pty pair (and socat between its ends) is full after about 250 (~3.5
  // messages a frame). Under ASan a synthetic frame takes ~100 ms with another test beside
  // it: the wait allows four times the others' (ctest's TIMEOUT is 600 s).
  REQUIRE(app.wait(4 * kAppTimeoutMs, &exitStatus));
  const std::string err = readText(appErr);
  INFO(err);
  CHECK(exitStatus == 0);
  CHECK(csvRows(readText(csv)).size() == 600);  // every frame tracked and written
  const size_t at = err.find("stopped after 600 frames");
  REQUIRE(at != std::string::npos);
  const size_t drop = err.find("tx-dropped ", at);
  REQUIRE(drop != std::string::npos);
  CHECK(std::atoi(err.c_str() + drop + 11) > 0);
}
TEST_CASE("--mavlink-udp: the same messages to a loopback peer, commands answered to it") {
  // The ground station's end: a UDP socket on loopback, decoding with the official library.
  LoopbackUdp gcsSocket;
  const int gcs = gcsSocket.fd;
  const char* target = gcsSocket.target;
  TempDir tmp;
  const std::string appErr = tmp / "app.err";
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--protocol", "mavlink", "--mavlink-udp", target,
                        "--no-gt",        "--frames",   "100000",  "--quiet",       nullptr};
  REQUIRE(app.start(argv, nullptr, appErr.c_str()));
  INFO(readText(appErr));
  official::Decoder dec;
  std::vector<official::Decoded> got;
  int badCrc = 0, notOneMessage = 0;
  sockaddr_in from{};
  socklen_t fromLen = sizeof from;
  auto until = [&](auto pred) {
    return waitFor(
        [&] {
          uint8_t buf[600];
          pollfd p{gcs, POLLIN, 0};
          if (::poll(&p, 1, 10) <= 0) return false;
          fromLen = sizeof from;
          const ssize_t n =
              ::recvfrom(gcs, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &fromLen);
          // One whole message per datagram, as a router expects.
          if (n > 0 && (buf[0] != kStx || n != static_cast<ssize_t>(kHeaderBytes + buf[1] + 2)))
            ++notOneMessage;
          bool hit = false;
          for (ssize_t i = 0; i < n; ++i) {
            official::Decoded d;
            const int r = dec.push(buf[i], &d);
            badCrc += r < 0;
            if (r != 1) continue;
            got.push_back(d);
            hit = hit || pred(d);
          }
          return hit;
        },
        30000);
  };
  REQUIRE(until([](const official::Decoded& d) { return d.msgId == kMsgHeartbeat; }));
  REQUIRE(until([](const official::Decoded& d) { return status(d, kTrackingStatusIdle); }));
  float p[7] = {0.4375f, 0.5f, 0.5f, 0.625f, 0, 0, 0};
  uint8_t w[300];
  const size_t n = official::encodeCommandLong(kGcsSys, kGcsComp, 1, 100, kCmdCameraTrackRectangle,
                                               p, w, sizeof w);
  REQUIRE(::sendto(gcs, w, n, 0, reinterpret_cast<sockaddr*>(&from), fromLen) ==
          static_cast<ssize_t>(n));
  REQUIRE(until([](const official::Decoded& d) { return ackOf(d, kCmdCameraTrackRectangle); }));
  REQUIRE(until([](const official::Decoded& d) { return status(d, kTrackingStatusActive); }));
  CHECK(badCrc == 0);
  CHECK(notOneMessage == 0);
  int accepted = 0;
  for (const auto& d : got)
    accepted += ackOf(d, kCmdCameraTrackRectangle) && d.ackResult == kResultAccepted;
  CHECK(accepted == 1);

  // Noise (a cut header), then 200 commands in one datagram framed by the official
  // library: the noise reaches no further than its datagram, every command is answered.
  const uint8_t cut[] = {kStx, 33, 0, 0, 9, kGcsSys};
  REQUIRE(::sendto(gcs, cut, sizeof cut, 0, reinterpret_cast<sockaddr*>(&from), fromLen) ==
          static_cast<ssize_t>(sizeof cut));
  std::vector<uint8_t> many;
  for (int i = 0; i < 200; ++i) {
    const float none[7] = {0, 0, 0, 0, 0, 0, 0};
    const size_t k = official::encodeCommandLong(
        kGcsSys, kGcsComp, 1, 100, static_cast<uint16_t>(40000 + i), none, w, sizeof w);
    many.insert(many.end(), w, w + k);
  }
  REQUIRE(::sendto(gcs, many.data(), many.size(), 0, reinterpret_cast<sockaddr*>(&from), fromLen) ==
          static_cast<ssize_t>(many.size()));
  REQUIRE(until([](const official::Decoded& d) { return ackOf(d, 40000 + 199); }));
  int answered = 0;
  for (const auto& d : got)
    answered += d.msgId == kMsgCommandAck && d.ackCommand >= 40000 && d.ackCommand < 40200 &&
                d.ackResult == kResultUnsupported;
  CHECK(answered == 200);
  app.signal(SIGTERM);
  int exitStatus = -1;
  REQUIRE(app.wait(30000, &exitStatus));
  CHECK(exitStatus == 0);
  // Even --quiet names the link's losses, by its own name.
  const std::string err = readText(appErr);
  CHECK(err.find("udp sent ") != std::string::npos);
  CHECK(err.find(" rx-errors 1 (crc 0, length 1, unknown 0) ") != std::string::npos);
  CHECK(err.find("serial") == std::string::npos);
}

TEST_CASE("--mavlink-key: signed both ways over UDP; unsigned commands refused; bad keys exit 2") {
  TempDir tmp;
  const std::string keyPath = tmp / "key", appErr = tmp / "app.err";
  uint8_t key[32];
  for (int i = 0; i < 32; ++i) key[i] = static_cast<uint8_t>(0xA5 ^ i);
  writeText(keyPath, std::string(reinterpret_cast<const char*>(key), 32));
  // A key others can read, or of another size: refused before the run, naming the file.
  REQUIRE(::chmod(keyPath.c_str(), 0644) == 0);
  LoopbackUdp gcsSocket;
  const char* base[] = {CUETRACK_APP_BIN, "--protocol",    "mavlink",       "--mavlink-udp",
                        gcsSocket.target, "--mavlink-key", keyPath.c_str(), "--no-gt",
                        "--quiet",        "--frames",      "100000",        nullptr};
  {
    ChildProcess app;
    REQUIRE(app.start(base, nullptr, appErr.c_str()));
    int status = -1;
    REQUIRE(app.wait(kAppTimeoutMs, &status));
    CHECK(status == 2);
    CHECK(readText(appErr).find(keyPath + ": the key is open to group or others (mode 644)") !=
          std::string::npos);
  }
  REQUIRE(::chmod(keyPath.c_str(), 0600) == 0);
  ChildProcess app;
  REQUIRE(app.start(base, nullptr, appErr.c_str()));
  const int gcs = gcsSocket.fd;
  sockaddr_in from{};
  socklen_t fromLen = sizeof from;
  int acks = 0, unsignedFrames = 0, frames = 0;
  auto until = [&](int wantAcks) {
    return waitFor(
        [&] {
          uint8_t buf[600];
          pollfd p{gcs, POLLIN, 0};
          if (::poll(&p, 1, 10) <= 0) return false;
          fromLen = sizeof from;
          const ssize_t n =
              ::recvfrom(gcs, buf, sizeof buf, 0, reinterpret_cast<sockaddr*>(&from), &fromLen);
          if (n <= 0) return false;
          ++frames;
          unsignedFrames += !official::verifiesSigned(buf, static_cast<size_t>(n), key);
          acks += buf[7] == kMsgCommandAck && buf[8] == 0 && buf[9] == 0;
          return acks >= wantAcks;
        },
        30000);
  };
  REQUIRE(until(0));  // a first datagram: the address to answer
  const float none[7] = {0, 0, 0, 0, 0, 0, 0};
  uint8_t w[300];
  // Unsigned: refused, no answer. Then signed by the official library: answered.
  size_t n = official::encodeCommandLong(kGcsSys, kGcsComp, 1, 100, 40000, none, w, sizeof w);
  REQUIRE(::sendto(gcs, w, n, 0, reinterpret_cast<sockaddr*>(&from), fromLen) ==
          static_cast<ssize_t>(n));
  n = official::encodeSignedCommandLong(kGcsSys, kGcsComp, 1, 100, 40001, none, key, 0,
                                        platform::signingTimestampNow(), w, sizeof w);
  REQUIRE(::sendto(gcs, w, n, 0, reinterpret_cast<sockaddr*>(&from), fromLen) ==
          static_cast<ssize_t>(n));
  REQUIRE(until(1));
  CHECK(acks == 1);
  CHECK(unsignedFrames == 0);  // everything cuetrack sent is signed with the key
  app.signal(SIGTERM);
  int status = -1;
  REQUIRE(app.wait(30000, &status));
  CHECK(status == 0);
  CHECK(readText(appErr).find(" refused 1") != std::string::npos);
}
#endif
