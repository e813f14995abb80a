// End to end with the real binaries over socat pseudo-terminal pairs:
//   cuetrack --serial A  ->  pty  ->  cuetrack-listen B   (tracks equal)
//   commands over the pty start/reset/stop the app; garbage both ways is rejected and
//   counted and the stream resynchronises; the app survives its serial peer going
//   away and reconnects when it returns.
// Every wait polls an observable condition with a bound; no sleep synchronises.
#include <catch2/catch.hpp>

#include <signal.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <random>
#include <string>
#include <vector>

#include "Process.hpp"
#include "Skip.hpp"
#include "TempDir.hpp"
#include "TestPrograms.hpp"
#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"
#include "cuetrack_proto.h"

using namespace cuetrack;
using namespace cuetrack::test;
using platform::IoStatus;
using platform::SerialPort;

namespace {

constexpr int kAppTimeoutMs = 120000;  // generous: 2 cores shared by many builds

// CSV rows without the first column (seq: each link numbers its own messages).
std::vector<std::string> rowsWithoutSeq(const std::string& csv) {
  std::vector<std::string> out;
  for (const std::string& l : lines(csv)) {
    const size_t comma = l.find(',');
    if (comma != std::string::npos) out.push_back(l.substr(comma + 1));
  }
  return out;
}

// Host end of the protocol over a real port.
struct HostPort {
  SerialPort port;
  ctp_decoder_t dec{};
  std::vector<ctp_message_t> got;
  HostPort() { ctp_decoder_init(&dec); }
  // Reads until pred(message) is true for a new message, or timeoutMs passes.
  template <typename P>
  bool until(P pred, int timeoutMs) {
    bool hit = false;
    waitFor(
        [&] {
          uint8_t buf[512];
          const platform::IoResult r = port.read(buf, sizeof buf, 10);
          for (size_t i = 0; i < r.bytes && !hit; ++i) {
            ctp_frame_t f;
            if (ctp_decoder_push(&dec, buf[i], &f, nullptr) != CTP_PUSH_FRAME) continue;
            ctp_message_t m;
            if (ctp_parse_message(&f, &m) != CTP_OK) continue;
            got.push_back(m);
            hit = pred(m);
          }
          return hit;
        },
        timeoutMs);
    return hit;
  }
  void send(const ctp_command_t& c) {
    uint8_t w[CTP_MAX_WIRE];
    const size_t n = ctp_encode_command(&c, w, sizeof w);
    REQUIRE(port.write(w, n).bytes == n);
  }
  void sendRaw(const uint8_t* b, size_t n) {
    size_t done = 0;
    waitFor(
        [&] {
          const platform::IoResult r = port.write(b + done, n - done);
          done += r.bytes;
          return done == n;
        },
        5000);
    REQUIRE(done == n);
  }
};

bool isTrack(const ctp_message_t& m, uint8_t state) {
  return m.type == CTP_MSG_TRACK && m.u.track.state == state;
}

// Heartbeats numbered from..to as the device sends them, after a frame delimiter.
std::vector<uint8_t> heartbeats(uint32_t from, uint32_t to) {
  std::vector<uint8_t> wire{0};
  for (uint32_t s = from; s <= to; ++s) {
    ctp_heartbeat_t h{};
    h.seq = s;
    uint8_t w[CTP_MAX_WIRE];
    const size_t n = ctp_encode_heartbeat(&h, w, sizeof w);
    wire.insert(wire.end(), w, w + n);
  }
  return wire;
}

bool haveSocat() {
  return fileExists("/usr/bin/socat");
}

// Runs cuetrack on a recording, CSV to `csv`, stderr to `err`; its exit status.
int runOnRecording(const std::string& rec, const std::string& csv, const std::string& err) {
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--source", rec.c_str(), "--out",
                        csv.c_str(),      "--quiet",  nullptr};
  REQUIRE(app.start(argv, nullptr, err.c_str()));
  int status = -1;
  REQUIRE(app.wait(kAppTimeoutMs, &status));
  return status;
}

}  // namespace

TEST_CASE("tracks sent by cuetrack over a pty equal the tracks cuetrack-listen decodes") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string csvListen = tmp.file("listen.csv"), csvApp = tmp.file("app.csv");
  const std::string listenErr = tmp.file("listen.err"), appErr = tmp.file("app.err");
  ChildProcess listener;
  const char* largv[] = {
      CUETRACK_LISTEN_BIN, pty.b(), "--baud",         "921600", "--csv", csvListen.c_str(),
      "--tracks",          "40",    "--idle-timeout", "60",     nullptr};
  REQUIRE(listener.start(largv, nullptr, listenErr.c_str()));
  // The listener flushes stale input when it opens the port: start the app after that.
  REQUIRE(waitFor([&] { return slurp(listenErr).find("listening") != std::string::npos; }, 10000));

  ChildProcess app;
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.a(), "--baud",  "921600", "--out",
                         csvApp.c_str(),   "--frames", "40",    "--quiet", nullptr};
  REQUIRE(app.start(aargv, nullptr, appErr.c_str()));
  int appStatus = -1, listenStatus = -1;
  REQUIRE(app.wait(kAppTimeoutMs, &appStatus));
  INFO(slurp(appErr));
  REQUIRE(appStatus == 0);
  REQUIRE(listener.wait(30000, &listenStatus));
  INFO(slurp(listenErr));
  REQUIRE(listenStatus == 0);

  const std::vector<std::string> a = rowsWithoutSeq(slurp(csvApp));
  const std::vector<std::string> l = rowsWithoutSeq(slurp(csvListen));
  REQUIRE(a.size() == 41);  // header + 40 frames
  REQUIRE(l == a);
  CHECK(a[5].find("tracking") != std::string::npos);
  CHECK(slurp(listenErr).find("rejected 0") != std::string::npos);
  CHECK(slurp(listenErr).find("seq gaps 0") != std::string::npos);
}

TEST_CASE("commands over a pty start, reset and stop the app; garbage gets ERROR replies") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  HostPort host;
  REQUIRE(host.port.open(pty.b(), 115200));
  const std::string appErr = tmp.file("app.err");
  ChildProcess app;
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.a(),   "--no-gt",
                         "--frames",       "100000",   "--quiet", nullptr};
  REQUIRE(app.start(aargv, nullptr, appErr.c_str()));
  INFO(slurp(appErr));
  REQUIRE(host.until([](const ctp_message_t& m) { return isTrack(m, CTP_STATE_IDLE); }, 30000));

  ctp_command_t start{};
  start.type = CTP_CMD_START;
  start.id = 100;
  start.box_px[0] = 280;
  start.box_px[1] = 240;
  start.box_px[2] = 40;
  start.box_px[3] = 60;
  host.send(start);
  REQUIRE(host.until(
      [](const ctp_message_t& m) { return m.type == CTP_MSG_ACK && m.u.ack.cmd_id == 100; },
      30000));
  REQUIRE(host.until([](const ctp_message_t& m) { return isTrack(m, CTP_STATE_TRACKING); }, 30000));

  ctp_command_t reset{};
  reset.type = CTP_CMD_RESET;
  reset.id = 101;
  host.send(reset);
  REQUIRE(host.until(
      [](const ctp_message_t& m) { return m.type == CTP_MSG_ACK && m.u.ack.cmd_id == 101; },
      30000));
  REQUIRE(host.until([](const ctp_message_t& m) { return isTrack(m, CTP_STATE_IDLE); }, 30000));

  // Random bytes, a truncated command and a corrupted one, each ended by a delimiter.
  std::mt19937 rng(7);
  std::vector<uint8_t> junk;
  for (int i = 0; i < 300; ++i) junk.push_back(static_cast<uint8_t>(rng()));
  junk.push_back(0);
  uint8_t w[CTP_MAX_WIRE];
  const size_t n = ctp_encode_command(&start, w, sizeof w);
  junk.insert(junk.end(), w, w + 6);  // truncated...
  junk.push_back(0);                  // ...and cut off
  w[3] ^= 0x40;                       // corrupted
  junk.insert(junk.end(), w, w + n);
  host.sendRaw(junk.data(), junk.size());
  REQUIRE(host.until(
      [](const ctp_message_t& m) { return m.type == CTP_MSG_ERROR && m.u.error.cmd_type == 0; },
      30000));
  // The stream resynchronised: a good command still works and frames keep coming.
  ctp_command_t rate{};
  rate.type = CTP_CMD_SET_RATE;
  rate.id = 102;
  rate.rate_hz = 0;
  host.send(rate);
  REQUIRE(host.until(
      [](const ctp_message_t& m) { return m.type == CTP_MSG_ACK && m.u.ack.cmd_id == 102; },
      30000));
  REQUIRE(host.until([](const ctp_message_t& m) { return m.type == CTP_MSG_TRACK; }, 30000));

  ctp_command_t stop{};
  stop.type = CTP_CMD_STOP;
  stop.id = 103;
  host.send(stop);
  REQUIRE(host.until(
      [](const ctp_message_t& m) { return m.type == CTP_MSG_ACK && m.u.ack.cmd_id == 103; },
      30000));
  int status = -1;
  REQUIRE(app.wait(30000, &status));
  CHECK(status == 0);
  CHECK(slurp(appErr).find("STOP command") == std::string::npos);  // --quiet: no summary
}

TEST_CASE("cuetrack-listen --send starts tracking and prints the ACK") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string appErr = tmp.file("app.err"), listenOut = tmp.file("listen.out"),
                    listenErr = tmp.file("listen.err");
  ChildProcess app;
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.a(),   "--no-gt",
                         "--frames",       "100000",   "--quiet", nullptr};
  REQUIRE(app.start(aargv, nullptr, appErr.c_str()));
  ChildProcess listener;
  const char* largv[] = {CUETRACK_LISTEN_BIN,   pty.b(),    "--send",
                         "start:280,240,40,60", "--tracks", "30",
                         "--idle-timeout",      "60",       nullptr};
  REQUIRE(listener.start(largv, listenOut.c_str(), listenErr.c_str()));
  REQUIRE(waitFor([&] { return slurp(listenOut).find(" tracking box=") != std::string::npos; },
                  kAppTimeoutMs));
  int status = -1;
  REQUIRE(listener.wait(kAppTimeoutMs, &status));
  CHECK(status == 0);
  const std::string out = slurp(listenOut);
  INFO(out.substr(0, 2000));
  CHECK(out.find("ack seq=") != std::string::npos);
  CHECK(out.find(" start id=1") != std::string::npos);
  app.signal(SIGTERM);
  REQUIRE(app.wait(30000, &status));
  CHECK(status == 0);
}

TEST_CASE("garbage from the device side is rejected and counted by the listener") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string csv = tmp.file("l.csv"), listenErr = tmp.file("l.err");
  ChildProcess listener;
  const char* largv[] = {CUETRACK_LISTEN_BIN, pty.b(), "--csv", csv.c_str(), "--tracks", "10",
                         "--idle-timeout",    "30",    nullptr};
  REQUIRE(listener.start(largv, nullptr, listenErr.c_str()));
  REQUIRE(waitFor([&] { return slurp(listenErr).find("listening") != std::string::npos; }, 10000));
  HostPort device;  // plays the device on the other end
  REQUIRE(device.port.open(pty.a(), 115200));
  std::mt19937 rng(3);
  std::vector<uint8_t> stream;
  for (uint32_t i = 0; i < 10; ++i) {
    ctp_track_t t{};
    t.seq = i;
    t.time_us = 1000u * i;
    t.state = CTP_STATE_TRACKING;
    t.box_px[2] = 10;
    t.box_px[3] = 10;
    uint8_t w[CTP_MAX_WIRE];
    const size_t n = ctp_encode_track(&t, w, sizeof w);
    // Before each good frame: random bytes, a truncated copy, a bit-flipped copy.
    for (int k = 0; k < 40; ++k) stream.push_back(static_cast<uint8_t>(rng()));
    stream.push_back(0);
    stream.insert(stream.end(), w, w + n / 2);
    stream.push_back(0);
    std::vector<uint8_t> flipped(w, w + n);
    flipped[5] ^= 0x08;
    stream.insert(stream.end(), flipped.begin(), flipped.end());
    stream.insert(stream.end(), w, w + n);
  }
  device.sendRaw(stream.data(), stream.size());
  int status = -1;
  REQUIRE(listener.wait(30000, &status));
  const std::string err = slurp(listenErr);
  INFO(err);
  REQUIRE(status == 0);
  const std::vector<std::string> rows = lines(slurp(csv));
  REQUIRE(rows.size() == 11);
  CHECK(rows[10].find("9,9000,tracking") == 0);
  // At least the 10 truncated + 10 flipped frames were refused.
  const size_t at = err.find("rejected ");
  REQUIRE(at != std::string::npos);
  CHECK(std::atoi(err.c_str() + at + 9) >= 20);
}

TEST_CASE("when the serial peer goes away the app reports it, keeps tracking, reconnects") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string appErr = tmp.file("app.err"), appCsv = tmp.file("app.csv");
  ChildProcess app;
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.a(),   "--out", appCsv.c_str(),
                         "--frames",       "100000",   "--quiet", nullptr};
  REQUIRE(app.start(aargv, nullptr, appErr.c_str()));
  {
    HostPort host;
    REQUIRE(host.port.open(pty.b(), 115200));
    REQUIRE(host.until([](const ctp_message_t& m) { return m.type == CTP_MSG_TRACK; }, 30000));
  }
  pty.stop();  // the peer (and the device node) vanish
  REQUIRE(waitFor([&] { return slurp(appErr).find("tracking continues") != std::string::npos; },
                  30000));
  REQUIRE(app.running());
  const size_t rowsBefore = lines(slurp(appCsv)).size();
  REQUIRE(waitFor([&] { return lines(slurp(appCsv)).size() > rowsBefore + 5; }, 60000));
  // Still tracking (target from the scene's ground truth), not just reading frames.
  CHECK(lines(slurp(appCsv))[rowsBefore + 2].find(",tracking,") != std::string::npos);

  REQUIRE(pty.start());
  REQUIRE(waitFor([&] { return slurp(appErr).find("reconnected") != std::string::npos; }, 30000));
  HostPort again;
  REQUIRE(again.port.open(pty.b(), 115200));
  REQUIRE(again.until([](const ctp_message_t& m) { return m.type == CTP_MSG_TRACK; }, 30000));
  app.signal(SIGTERM);
  int status = -1;
  REQUIRE(app.wait(30000, &status));
  INFO(slurp(appErr));
  CHECK(status == 0);
}

TEST_CASE("cuetrack runs on a fakenect recording and takes the target from its ground truth") {
  TempDir tmp;
  const std::string rec = tmp.file("rec");
  {
    SceneSpec spec;
    REQUIRE(makeScene("moving", &spec));
    spec.frameCount = 8;
    static SyntheticSource synth(spec, 5);
    static FrameSlot slot;
    FakenectWriter writer;
    INFO(writer.error());
    REQUIRE(writer.open(rec.c_str(), "moving"));
    while (synth.next(slot) == ReadStatus::Ok) REQUIRE(writer.write(slot));
    REQUIRE(writer.close());
  }
  const std::string csv = tmp.file("out.csv"), appErr = tmp.file("app.err");
  int status = runOnRecording(rec, csv, appErr);
  INFO(slurp(appErr));
  REQUIRE(status == 0);
  const std::vector<std::string> rows = lines(slurp(csv));
  REQUIRE(rows.size() == 9);  // header + every recorded frame
  CHECK(rows[1].find(",tracking,") != std::string::npos);
  CHECK(rows[8].find(",idle,") == std::string::npos);

  // A broken path gives one line naming it and exit code 1 (a source failure).
  ChildProcess bad;
  const std::string missing = tmp.file("nothing-here");
  const char* bargv[] = {CUETRACK_APP_BIN, "--source", missing.c_str(), "--quiet", nullptr};
  REQUIRE(bad.start(bargv, nullptr, appErr.c_str()));
  REQUIRE(bad.wait(30000, &status));
  CHECK(status == 1);
  CHECK(slurp(appErr).find(missing) != std::string::npos);
}

TEST_CASE("a recording whose frames change size, or whose ground truth is refused, fails") {
  TempDir tmp;
  const std::string rec = tmp.file("rec"), small = tmp.file("small"), gt = tmp.file("gt");
  const std::string synth = std::string(CUETRACK_SYNTH_BIN) + " --scene moving --frames 8 ";
  // Frame 5 of rec replaced by the 320x240 one (same file names: same timestamps).
  const std::string make = synth + "--out " + rec + " >/dev/null && " + synth +
                           "--size 320x240 --out " + small + " >/dev/null && cd " + tmp.path() +
                           " && for p in r d; do f=$(grep \"^$p-\" rec/INDEX.txt | sed -n 6p)"
                           " && cp small/$f rec/$f || exit 1; done && cd - >/dev/null && " +
                           synth + "--out " + gt +
                           " >/dev/null && sed -i '2s/.*/0 -0.5 0.5 0.05 0.1/' " + gt +
                           "/groundtruth.txt";
  REQUIRE(std::system(make.c_str()) == 0);
  const std::string csv = tmp.file("out.csv"), appErr = tmp.file("app.err");
  int status = runOnRecording(rec, csv, appErr);
  INFO(slurp(appErr));
  CHECK(status == 1);  // source failed: the tracker would skip the frame, saying "tracking"
  CHECK(slurp(appErr).find(rec) != std::string::npos);
  CHECK(lines(slurp(csv)).size() <= 6);  // header + frames 0..4 at most

  // The ground truth's box lies left of the image: exit 4, naming the file and frame.
  ChildProcess refused;
  const char* gargv[] = {CUETRACK_APP_BIN, "--source", gt.c_str(), "--quiet", nullptr};
  REQUIRE(refused.start(gargv, "/dev/null", appErr.c_str()));
  REQUIRE(refused.wait(kAppTimeoutMs, &status));
  INFO(slurp(appErr));
  CHECK(status == 4);
  CHECK(slurp(appErr).find(gt + "/groundtruth.txt: frame 0: box -320,240,32,48 refused") !=
        std::string::npos);
}

TEST_CASE("no way for a target to arrive is exit 2 in one line; a failed run has no summary") {
  TempDir tmp;
  const std::string rec = tmp.file("rec"), err = tmp.file("err"), out = tmp.file("out");
  const std::string make = std::string(CUETRACK_SYNTH_BIN) + " --scene moving --frames 4 --out " +
                           rec + " >/dev/null && rm " + rec + "/groundtruth.txt";
  REQUIRE(std::system(make.c_str()) == 0);
  auto runApp = [&](std::vector<const char*> argv) {
    argv.push_back(nullptr);
    ChildProcess p;
    REQUIRE(p.start(argv.data(), out.c_str(), err.c_str()));
    int status = -1;
    REQUIRE(p.wait(kAppTimeoutMs, &status));
    return status;
  };
  // A recording without ground truth, no --box, --select or link: before any banner.
  CHECK(runApp({CUETRACK_APP_BIN, "--source", rec.c_str()}) == 2);
  CHECK(slurp(err) == "cuetrack: " + rec + ": nothing to track: no ground truth (" + rec +
                          "/groundtruth.txt not found); give --box X,Y,W,H, --select, or a link "
                          "for a START (--serial DEV, --mavlink-udp HOST:PORT)\n");
  CHECK(slurp(out).empty());
  for (const std::vector<const char*>& args :
       {std::vector<const char*>{CUETRACK_APP_BIN, "--no-gt", "--frames", "3"},
        std::vector<const char*>{CUETRACK_APP_BIN, "--source", "kinect"}}) {
    CHECK(runApp(args) == 2);
    const std::string e = slurp(err);
    INFO(e);
    CHECK(std::count(e.begin(), e.end(), '\n') == 1);
    CHECK(e.find(": nothing to track") != std::string::npos);
  }
  // With a box it runs, and the banner names no ground-truth file.
  CHECK(runApp({CUETRACK_APP_BIN, "--source", rec.c_str(), "--box", "291,266,30,52"}) == 0);
  CHECK(slurp(err).find("groundtruth.txt") == std::string::npos);
  // A failed run (the box refused, exit 4): its line, no summary, no next: line.
  CHECK(runApp({CUETRACK_APP_BIN, "--source", rec.c_str(), "--box", "700,10,30,30"}) == 4);
  const std::string e = slurp(err);
  INFO(e);
  CHECK(e.find("--box 700,10,30,30 refused by the tracker: box does not intersect the image (the "
               "image is 640x480)") != std::string::npos);
  CHECK(e.find("summary:") == std::string::npos);
  CHECK(e.find("next:") == std::string::npos);
}

TEST_CASE("cuetrack-listen exits 1 naming the port when it goes away") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string listenErr = tmp.file("l.err");
  ChildProcess listener;
  const char* largv[] = {CUETRACK_LISTEN_BIN, pty.b(), "--idle-timeout", "60", nullptr};
  REQUIRE(listener.start(largv, nullptr, listenErr.c_str()));
  REQUIRE(waitFor([&] { return slurp(listenErr).find("listening") != std::string::npos; }, 10000));
  pty.stop();
  int status = -1;
  REQUIRE(listener.wait(30000, &status));
  INFO(slurp(listenErr));
  CHECK(status == 1);
  CHECK(slurp(listenErr).find(std::string(pty.b()) + ": the port went away") != std::string::npos);
}

TEST_CASE("cuetrack-listen --reconnect waits for the port and reports the seq gap across it") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string listenErr = tmp.file("l.err"), listenOut = tmp.file("l.out");
  ChildProcess listener;
  const char* largv[] = {CUETRACK_LISTEN_BIN, pty.b(), "--reconnect", nullptr};
  REQUIRE(listener.start(largv, listenOut.c_str(), listenErr.c_str()));
  REQUIRE(waitFor([&] { return slurp(listenErr).find("listening") != std::string::npos; }, 10000));
  // The device: heartbeats seq 0..2, then the line goes, then seq 10.
  {
    HostPort device;
    REQUIRE(device.port.open(pty.a(), 115200));
    const std::vector<uint8_t> wire = heartbeats(0, 2);
    device.sendRaw(wire.data(), wire.size());
    REQUIRE(waitFor([&] { return lines(slurp(listenOut)).size() >= 3; }, 10000));
  }
  pty.stop();
  REQUIRE(
      waitFor([&] { return slurp(listenErr).find("waiting for it") != std::string::npos; }, 10000));
  CHECK(listener.running());
  REQUIRE(pty.start());
  REQUIRE(waitFor([&] { return slurp(listenErr).find("the port is back") != std::string::npos; },
                  10000));
  {
    HostPort device;
    REQUIRE(device.port.open(pty.a(), 115200));
    const std::vector<uint8_t> wire = heartbeats(10, 10);
    device.sendRaw(wire.data(), wire.size());
    REQUIRE(waitFor([&] { return slurp(listenErr).find("seq 10 after 2") != std::string::npos; },
                    10000));
  }
  listener.signal(SIGTERM);
  int status = -1;
  REQUIRE(listener.wait(30000, &status));
  const std::string err = slurp(listenErr);
  INFO(err);
  CHECK(status == 0);
  CHECK(err.find("seq 10 after 2: 7 messages lost") != std::string::npos);
  CHECK(err.find("seq gaps 7 (seq first 0 last 10, device restarts 0)") != std::string::npos);
}

TEST_CASE("a restarted listener with --state reports the messages lost while it was away") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string state = tmp.file("listen.state");
  HostPort device;
  REQUIRE(device.port.open(pty.a(), 115200));
  auto send = [&](uint32_t from, uint32_t to) {
    const std::vector<uint8_t> wire = heartbeats(from, to);
    device.sendRaw(wire.data(), wire.size());
  };
  auto runListener = [&](const std::string& errPath, uint32_t from, uint32_t to) {
    ChildProcess listener;
    const char* largv[] = {CUETRACK_LISTEN_BIN, pty.b(), "--state", state.c_str(), nullptr};
    REQUIRE(listener.start(largv, "/dev/null", errPath.c_str()));
    REQUIRE(waitFor([&] { return slurp(errPath).find("listening") != std::string::npos; }, 10000));
    send(from, to);
    const std::string last = "last_seq " + std::to_string(to);
    REQUIRE(waitFor([&] { return slurp(state).find(last) == 0; }, 10000));
    listener.signal(SIGTERM);
    int status = -1;
    REQUIRE(listener.wait(30000, &status));
    CHECK(status == 0);
  };
  runListener(tmp.file("1.err"), 0, 4);
  // Messages 5..65 went out while no listener ran (the device numbers every message it
  // sends, read or not): the next run starts at 66.
  runListener(tmp.file("2.err"), 66, 70);
  const std::string err = slurp(tmp.file("2.err"));
  INFO(err);
  CHECK(err.find("the last run ended after seq 4") != std::string::npos);
  CHECK(err.find("seq 66 after 4: 61 messages lost") != std::string::npos);
  CHECK(err.find("seq gaps 61 (seq first 66 last 70") != std::string::npos);
}

TEST_CASE("two listeners on one port: the second is refused, naming the first's PID") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  TempDir tmp;
  PtyPair pty;
  REQUIRE(pty.start());
  const std::string err1 = tmp.file("1.err"), err2 = tmp.file("2.err");
  ChildProcess first;
  const char* argv1[] = {CUETRACK_LISTEN_BIN, pty.b(), nullptr};
  REQUIRE(first.start(argv1, "/dev/null", err1.c_str()));
  REQUIRE(waitFor([&] { return slurp(err1).find("listening") != std::string::npos; }, 10000));
  ChildProcess second;
  REQUIRE(second.start(argv1, "/dev/null", err2.c_str()));
  int status = -1;
  REQUIRE(second.wait(30000, &status));
  const std::string text = slurp(err2);
  INFO(text);
  CHECK(status == 1);
  CHECK(text.find(std::string(pty.b()) + ": in use by") != std::string::npos);
  CHECK(lines(text).size() == 1);  // one line
  // Where /run/lock is writable the lock file names the holder.
  if (access("/run/lock", W_OK) == 0)
    CHECK(text.find("in use by process " + std::to_string(first.pid())) != std::string::npos);
  // cuetrack itself is refused the same way.
  ChildProcess app;
  const std::string appErr = tmp.file("app.err");
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.b(), "--frames", "5", nullptr};
  REQUIRE(app.start(aargv, "/dev/null", appErr.c_str()));
  REQUIRE(app.wait(kAppTimeoutMs, &status));
  CHECK(status == 3);
  CHECK(slurp(appErr).find(std::string(pty.b()) + ": in use by") != std::string::npos);
  first.signal(SIGTERM);
  REQUIRE(first.wait(30000, &status));
}

TEST_CASE("SIGHUP ends cuetrack cleanly, with its final line, like SIGTERM") {
  TempDir tmp;
  const std::string err = tmp.file("err"), csv = tmp.file("t.csv");
  ChildProcess app;
  const char* argv[] = {CUETRACK_APP_BIN, "--frames", "1000000",   "--realtime",
                        "--stdout",       "--out",    csv.c_str(), nullptr};
  REQUIRE(app.start(argv, "/dev/null", err.c_str()));
  REQUIRE(waitFor([&] { return slurp(err).find("fps") != std::string::npos; }, kAppTimeoutMs));
  app.signal(SIGHUP);
  int status = -1;
  REQUIRE(app.wait(30000, &status));
  INFO(slurp(err));
  CHECK(status == 0);
  CHECK(slurp(err).find("stopped after") != std::string::npos);
  CHECK(slurp(err).find("(signal)") != std::string::npos);
  CHECK(lines(slurp(csv)).size() > 1);  // the rows of the frames before the signal
}

TEST_CASE("a damaged video frame stops cuetrack naming it, or is skipped and counted") {
  TempDir tmp;
  const std::string avi = tmp.file("Vid_D_damaged.avi");
  {
    ChildProcess synth;
    const char* sargv[] = {CUETRACK_SYNTH_BIN, "--scene", "moving", "--frames",  "12",
                           "--format",         "avi",     "--out",  avi.c_str(), nullptr};
    REQUIRE(synth.start(sargv, "/dev/null", tmp.file("synth.err").c_str()));
    int status = -1;
    REQUIRE(synth.wait(kAppTimeoutMs, &status));
    if (status != 0) CUETRACK_SKIP("this build writes no .avi (no OpenCV)");
  }
  damageAviFrame(avi, 7);

  const std::string err = tmp.file("err");
  ChildProcess strict;
  const char* argv1[] = {CUETRACK_APP_BIN, "--source", avi.c_str(), "--quiet", nullptr};
  REQUIRE(strict.start(argv1, "/dev/null", err.c_str()));
  int status = -1;
  REQUIRE(strict.wait(kAppTimeoutMs, &status));
  INFO(slurp(err));
  CHECK(status == 1);
  CHECK(slurp(err).find(avi + ": frame 7 is damaged") != std::string::npos);

  const std::string csv = tmp.file("t.csv");
  ChildProcess skipping;
  const char* argv2[] = {CUETRACK_APP_BIN, "--source",  avi.c_str(), "--skip-bad-frames",
                         "--out",          csv.c_str(), "--quiet",   nullptr};
  REQUIRE(skipping.start(argv2, "/dev/null", err.c_str()));
  REQUIRE(skipping.wait(kAppTimeoutMs, &status));
  INFO(slurp(err));
  CHECK(status == 0);
  CHECK(slurp(err).find("1 damaged frames skipped") != std::string::npos);  // even --quiet
  CHECK(lines(slurp(csv)).size() == 1 + 11);  // header + the 11 good frames
}

TEST_CASE("a tool whose stdout cannot be written (/dev/full) fails with one line") {
  TempDir tmp;
  const std::string err = tmp.file("err");
  const std::string rec = tmp.file("rec");
  const std::vector<std::vector<const char*>> cmds = {
      {CUETRACK_SYNTH_BIN, "--list"},
      {CUETRACK_SYNTH_BIN, "--help"},
      {CUETRACK_TRACKSPEED_BIN, "--frames", "1", "--particles", "50"},
      {CUETRACK_CONVERT_BIN, "synth:moving:2", "--bench"},
      {CUETRACK_SYNTH_BIN, "--scene", "moving", "--frames", "2", "--out", rec.c_str()},
      {CUETRACK_APP_BIN, "--frames", "2", "--quiet"},
      {CUETRACK_APP_BIN, "--help"},
  };
  for (const auto& c : cmds) {
    std::vector<const char*> argv = c;
    argv.push_back(nullptr);
    ChildProcess p;
    REQUIRE(p.start(argv.data(), "/dev/full", err.c_str()));
    int status = -1;
    REQUIRE(p.wait(kAppTimeoutMs, &status));
    const std::string text = slurp(err);
    INFO(c[0] << " " << c[1] << " -> " << text);
    CHECK(status != 0);
    CHECK(text.find("stdout") != std::string::npos);
  }
}

TEST_CASE("documented exit codes, each with one line naming what is at fault") {
  TempDir tmp;
  const std::string err = tmp.file("err"), out = tmp.file("out"), syn = tmp.file("syn");
  struct Case {
    std::vector<const char*> args;
    int code;
    const char* says;
  };
  const std::vector<Case> cases = {
      {{CUETRACK_APP_BIN, "--help"}, 0, ""},
      {{CUETRACK_APP_BIN, "--frames", "2", "--quiet"}, 0, ""},
      {{CUETRACK_APP_BIN, "--bogus"}, 2, "unknown option '--bogus'"},
      {{CUETRACK_APP_BIN, "--config", "9.9"}, 2, "--config 9.9: unknown preset"},
      {{CUETRACK_APP_BIN, "--serial", "/dev/null", "--baud", "300"}, 2, "--baud 300"},
      {{CUETRACK_APP_BIN, "--baud", "1234", "--frames", "2"}, 2, "--baud 1234"},
      {{CUETRACK_APP_BIN, "--source", "synth:nosuchscene"}, 2, "synth:nosuchscene"},
      {{CUETRACK_APP_BIN, "--serial", "/nonexistent/tty"}, 3, "/nonexistent/tty: cannot open"},
      {{CUETRACK_APP_BIN, "--out", "/dev/full", "--frames", "2"}, 3, "/dev/full"},
      {{CUETRACK_APP_BIN, "--box", "5000,5000,10,10", "--frames", "2"}, 4, "--box 5000,5000,10,10"},
      {{CUETRACK_APP_BIN, "--box", "1,1,inf,20", "--frames", "2"}, 2, "--box 1,1,inf,20: expected"},
      {{CUETRACK_APP_BIN, "--box", "1,1,1e30,1e30", "--frames", "2"}, 2, "--box 1,1,1e30,1e30:"},
      {{CUETRACK_APP_BIN, "--box", "nan,1,10,10", "--frames", "2"}, 2, "--box nan,1,10,10:"},
      {{CUETRACK_APP_BIN, "--seed", "-1", "--frames", "2"}, 2, "--seed -1"},
      {{CUETRACK_APP_BIN, "--baud", "0", "--frames", "2"}, 2, "--baud 0: unsupported"},
      {{CUETRACK_SYNTH_BIN, "--scene", "moving", "--out", syn.c_str(), "--seed", "-1"},
       2,
       "--seed '-1'"},
      {{CUETRACK_TRACKSPEED_BIN, "--help"}, 0, ""},
      {{CUETRACK_TRACKSPEED_BIN, "--frames", "1", "--particles", "50"}, 0, ""},
      {{CUETRACK_TRACKSPEED_BIN, "--particles", "abc"}, 2, "--particles 'abc'"},
      {{CUETRACK_TRACKSPEED_BIN, "--particles", "-1"}, 2, "--particles '-1'"},
      {{CUETRACK_TRACKSPEED_BIN, "--particles", "0"}, 2, "--particles '0'"},
      {{CUETRACK_TRACKSPEED_BIN, "--particles", "99999999"}, 2, "--particles '99999999'"},
      {{CUETRACK_TRACKSPEED_BIN, "--frames", "abc"}, 2, "--frames 'abc'"},
      {{CUETRACK_TRACKSPEED_BIN, "--weak", "33"}, 2, "--weak '33'"},
      {{CUETRACK_TRACKSPEED_BIN, "--scene", "nowhere"}, 2, "--scene 'nowhere'"},
      {{CUETRACK_LISTEN_BIN}, 2, "missing PORT"},
      {{CUETRACK_LISTEN_BIN, "/dev/null", "--send", "jump"}, 2, "command 'jump'"},
      {{CUETRACK_LISTEN_BIN, "/nonexistent/tty"}, 1, "/nonexistent/tty: cannot open"},
      // A newline in an argument does not split the error line.
      {{CUETRACK_APP_BIN, "--source", "no\nsuch"}, 1, "no?such"},
      // One convention (README): 2 for any bad command line, in every tool.
      {{CUETRACK_APP_BIN, "--frames", "0"}, 2, "--frames 0: expected a count >= 1"},
      {{CUETRACK_APP_BIN, "--box", "1,1,20,20", "--frames", "2", "--box", "5,5,20,20"},
       2,
       "--box given twice"},
      {{CUETRACK_LISTEN_BIN, "/dev/null", "--baud", "9600", "--baud", "19200"},
       2,
       "--baud given twice"},
      {{CUETRACK_LISTEN_BIN, "/dev/null", "--tracks", "0"}, 2, "--tracks 0"},
      {{CUETRACK_TRACKSPEED_BIN, "--hash", "--hash"}, 2, "--hash given twice"},
      {{CUETRACK_SYNTH_BIN, "--scene", "moving", "--scene", "box", "--out", syn.c_str()},
       2,
       "--scene given twice"},
  };
  for (const Case& c : cases) {
    std::vector<const char*> argv = c.args;
    argv.push_back(nullptr);
    ChildProcess p;
    REQUIRE(p.start(argv.data(), out.c_str(), err.c_str()));
    int status = -1;
    REQUIRE(p.wait(kAppTimeoutMs, &status));
    const std::string text = slurp(err);
    INFO(c.args[1 < c.args.size() ? 1 : 0] << " -> " << text);
    CHECK(status == c.code);
    CHECK(text.find(c.says) != std::string::npos);
    if (std::string(c.args[1 < c.args.size() ? 1 : 0]) == "--help")
      CHECK(slurp(out).find("exit codes") != std::string::npos);
  }
}
