// Text and CSV forms of track messages, quantisation of tracker results, and the
// text form of commands.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "cuetrack/platform/CommandText.hpp"
#include "cuetrack/platform/HostPort.hpp"
#include "cuetrack/platform/TrackText.hpp"

using namespace cuetrack;
using namespace cuetrack::platform;

TEST_CASE("tracker results are quantised to the wire message") {
  TrackResult r;
  r.state = TrackState::Tracking;
  r.box = {10.4f, 20.6f, 30.5f, 40.49f};
  r.hasPosition3d = true;
  r.positionMm[0] = -100.6f;
  r.positionMm[1] = 2.4f;
  r.positionMm[2] = 1500.5f;
  r.confidence = 0.5f;
  r.learned = true;
  ctp_track_t t = toTrackMessage(r, 123, 456, CTP_STATE_IDLE);
  CHECK(t.time_us == 123);
  CHECK(t.proc_us == 456);
  CHECK(t.state == CTP_STATE_TRACKING);
  CHECK(t.box_px[0] == 10);
  CHECK(t.box_px[1] == 21);
  CHECK(t.box_px[2] == 31);
  CHECK(t.box_px[3] == 40);
  CHECK(t.flags == (CTP_FLAG_HAS_3D | CTP_FLAG_LEARNED));
  r.occluded = true;
  CHECK(toTrackMessage(r, 123, 456, CTP_STATE_IDLE).flags ==
        (CTP_FLAG_HAS_3D | CTP_FLAG_LEARNED | CTP_FLAG_OCCLUDED));
  r.occluded = false;
  r.depthPredicted = true;
  CHECK(toTrackMessage(r, 123, 456, CTP_STATE_IDLE).flags ==
        (CTP_FLAG_HAS_3D | CTP_FLAG_LEARNED | CTP_FLAG_DEPTH_PREDICTED));
  r.depthPredicted = false;
  CHECK(t.centre_mm[0] == -101);
  CHECK(t.centre_mm[1] == 2);
  CHECK(t.centre_mm[2] == 1501);
  CHECK(t.confidence == 32768);

  SECTION("out-of-range values clamp instead of wrapping") {
    r.box = {1e9f, -1e9f, 5.f, 5.f};
    r.confidence = 7.f;
    t = toTrackMessage(r, 0, 0, CTP_STATE_TRACKING);
    CHECK(t.box_px[0] == 32767);
    CHECK(t.box_px[1] == -32768);
    CHECK(t.confidence == 65535);
  }
  SECTION("lost then still lost is LOST then SEARCHING") {
    r.state = TrackState::Lost;
    t = toTrackMessage(r, 0, 0, CTP_STATE_TRACKING);
    CHECK(t.state == CTP_STATE_LOST);
    t = toTrackMessage(r, 0, 0, CTP_STATE_LOST);
    CHECK(t.state == CTP_STATE_SEARCHING);
    t = toTrackMessage(r, 0, 0, CTP_STATE_SEARCHING);
    CHECK(t.state == CTP_STATE_SEARCHING);
  }
  SECTION("idle carries no box") {
    r.state = TrackState::Idle;
    t = toTrackMessage(r, 9, 0, CTP_STATE_TRACKING);
    CHECK(t.state == CTP_STATE_IDLE);
    CHECK(t.box_px[2] == 0);
    CHECK(t.flags == 0);
  }
}

TEST_CASE("track lines and CSV rows carry every field") {
  ctp_track_t t{};
  t.seq = 3;
  t.time_us = 66666;
  t.state = CTP_STATE_TRACKING;
  t.flags = CTP_FLAG_HAS_3D;
  t.box_px[0] = 1;
  t.box_px[1] = 2;
  t.box_px[2] = 3;
  t.box_px[3] = 4;
  t.centre_mm[0] = -5;
  t.centre_mm[1] = 6;
  t.centre_mm[2] = 700;
  t.confidence = 65535;
  t.proc_us = 8000;
  char buf[256];
  REQUIRE(formatTrackLine(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) ==
        "track seq=3 t=66666us tracking box=1,2,3,4 mm=-5,6,700 conf=1.000 proc=8000us\n");
  REQUIRE(formatTrackCsvRow(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) == "3,66666,tracking,1,2,3,4,1,-5,6,700,1.00000,0,8000,0,0\n");
  t.flags |= CTP_FLAG_OCCLUDED;
  REQUIRE(formatTrackLine(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) ==
        "track seq=3 t=66666us tracking box=1,2,3,4 mm=-5,6,700 conf=1.000 occluded proc=8000us\n");
  REQUIRE(formatTrackCsvRow(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) == "3,66666,tracking,1,2,3,4,1,-5,6,700,1.00000,0,8000,1,0\n");
  t.flags = CTP_FLAG_HAS_3D | CTP_FLAG_DEPTH_PREDICTED;
  REQUIRE(formatTrackLine(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) ==
        "track seq=3 t=66666us tracking box=1,2,3,4 mm=-5,6,700 conf=1.000 "
        "depth-predicted proc=8000us\n");
  REQUIRE(formatTrackCsvRow(t, buf, sizeof buf) > 0);
  CHECK(std::string(buf) == "3,66666,tracking,1,2,3,4,1,-5,6,700,1.00000,0,8000,0,1\n");
  CHECK(std::string(trackCsvHeader()).find("seq,time_us,state") == 0);
  REQUIRE(formatTrackLine(t, buf, 10) == 0);  // too small: refused, not truncated silently
}

TEST_CASE("command text parses the four commands and refuses anything else") {
  ctp_command_t c;
  char err[200];
  REQUIRE(parseCommandText("start:10,20,30,40", 7, &c, err, sizeof err));
  CHECK(c.type == CTP_CMD_START);
  CHECK(c.id == 7);
  CHECK(c.box_px[3] == 40);
  REQUIRE(parseCommandText("rate=15", 1, &c, err, sizeof err));
  CHECK(c.type == CTP_CMD_SET_RATE);
  CHECK(c.rate_hz == 15);
  REQUIRE(parseCommandText("reset", 2, &c, err, sizeof err));
  CHECK(c.type == CTP_CMD_RESET);
  REQUIRE(parseCommandText("stop", 3, &c, err, sizeof err));
  CHECK(c.type == CTP_CMD_STOP);

  const char* bad[] = {"", "start", "start:1,2,3", "start:1,2,3,0", "start:1,2,3,4,5",
                       "start:a,b,c,d", "rate:-1", "rate:1001", "rate:", "resetx", "stop:1",
                       "launch",
                       // Plain decimals only, as on every command line: no blanks, no hex.
                       "start: 1,2,3,4", "start:1,2,3, 4", "rate: 5", "start:0x10,2,3,4"};
  for (const char* b : bad) {
    INFO(b);
    err[0] = '\0';
    REQUIRE_FALSE(parseCommandText(b, 1, &c, err, sizeof err));
    REQUIRE(std::strlen(err) > 0);
  }
  char text[64];
  ctp_command_t s{};
  s.type = CTP_CMD_START;
  s.box_px[0] = -1;
  s.box_px[1] = 2;
  s.box_px[2] = 3;
  s.box_px[3] = 4;
  REQUIRE(formatCommandText(s, text, sizeof text) > 0);
  CHECK(std::string(text) == "start:-1,2,3,4");
}

TEST_CASE("HOST:PORT: names, IPv4 and [IPv6] with a port 1..65535; anything else refused") {
  char host[64];
  unsigned port = 0;
  REQUIRE(platform::splitHostPort("127.0.0.1:14550", host, sizeof host, &port));
  CHECK(std::string(host) == "127.0.0.1");
  CHECK(port == 14550);
  REQUIRE(platform::splitHostPort("router.local:1", host, sizeof host, &port));
  CHECK(std::string(host) == "router.local");
  REQUIRE(platform::splitHostPort("[::1]:65535", host, sizeof host, &port));
  CHECK(std::string(host) == "::1");
  CHECK(port == 65535);
  for (const char* bad : {"127.0.0.1", "127.0.0.1:", ":14550", "h:0", "h:65536", "h:-1", "h:12x",
                          "::1:14550", "[::1]14550", "[::1:5"}) {
    INFO(bad);
    CHECK_FALSE(platform::splitHostPort(bad, host, sizeof host, &port));
  }
  CHECK_FALSE(platform::splitHostPort("averyveryverylonghostname:1", host, 8, &port));
}
