// The flight controller's example (platform/protocol/example/fc_link.c) on the device's
// own messages: what it steers by, when it calls the board dead, what it counts.
#include <catch2/catch.hpp>

#include <cstring>
#include <vector>

#include "fc_link.h"

namespace {

std::vector<uint8_t> track(uint32_t seq, uint8_t state, bool has3d, int32_t zMm) {
  ctp_track_t t{};
  t.seq = seq;
  t.state = state;
  t.flags = has3d ? CTP_FLAG_HAS_3D : 0u;
  t.box_px[2] = t.box_px[3] = 40;
  t.centre_mm[0] = 120;
  t.centre_mm[1] = -35;
  t.centre_mm[2] = zMm;
  uint8_t w[CTP_MAX_WIRE];
  const size_t n = ctp_encode_track(&t, w, sizeof w);
  return std::vector<uint8_t>(w, w + n);
}

std::vector<uint8_t> heartbeat(uint32_t seq, uint8_t flags) {
  ctp_heartbeat_t h{};
  h.seq = seq;
  h.flags = flags;
  uint8_t w[CTP_MAX_WIRE];
  const size_t n = ctp_encode_heartbeat(&h, w, sizeof w);
  return std::vector<uint8_t>(w, w + n);
}

void feed(fc_link_t* l, const std::vector<uint8_t>& bytes, uint32_t nowMs) {
  for (uint8_t b : bytes) fc_link_on_byte(l, b, nowMs);
}

}  // namespace

TEST_CASE("fc_link steers only by a fresh, tracking TRACK with a 3D centre") {
  fc_link_t l;
  fc_link_init(&l);
  int32_t c[3] = {0, 0, 0};
  CHECK_FALSE(fc_link_alive(&l, 0));
  CHECK_FALSE(fc_link_target(&l, 0, c));
  feed(&l, track(0, CTP_STATE_TRACKING, true, 2500), 1000);
  REQUIRE(fc_link_target(&l, 1000, c));
  CHECK(c[0] == 120);
  CHECK(c[1] == -35);
  CHECK(c[2] == 2500);
  CHECK(fc_link_target(&l, 1000 + FC_LINK_FRESH_MS - 1, c));
  CHECK_FALSE(fc_link_target(&l, 1000 + FC_LINK_FRESH_MS, c));  // stale
  feed(&l, track(1, CTP_STATE_LOST, true, 2500), 1100);
  CHECK_FALSE(fc_link_target(&l, 1100, c));  // lost: the box is the last estimate
  feed(&l, track(2, CTP_STATE_TRACKING, false, 0), 1133);
  CHECK_FALSE(fc_link_target(&l, 1133, c));  // 2D only (colour): no centre to steer by
  feed(&l, track(3, CTP_STATE_TRACKING, true, 1800), 1166);
  CHECK(fc_link_target(&l, 1166, c));
  CHECK(c[2] == 1800);
  CHECK(l.lost == 0);
}

TEST_CASE("fc_link: alive while heartbeats come, dead after 2 s of silence; no-camera flag") {
  fc_link_t l;
  fc_link_init(&l);
  feed(&l, heartbeat(0, CTP_HB_NO_CAMERA), 5000);
  CHECK(fc_link_alive(&l, 5000));
  CHECK(l.camera_missing);
  feed(&l, heartbeat(1, CTP_HB_NO_CAMERA), 6000);
  CHECK(fc_link_alive(&l, 6000 + FC_LINK_DEAD_MS - 1));
  CHECK_FALSE(fc_link_alive(&l, 6000 + FC_LINK_DEAD_MS));
  feed(&l, track(2, CTP_STATE_IDLE, false, 0), 9000);  // the camera came: frames flow
  CHECK_FALSE(l.camera_missing);
  CHECK(fc_link_alive(&l, 9000));
  // The tick wraps after 49 days: differences stay right.
  fc_link_t w;
  fc_link_init(&w);
  feed(&w, heartbeat(0, 0), 0xFFFFFF00u);
  CHECK(fc_link_alive(&w, 0x00000100u));  // 512 ms later, across the wrap
  CHECK_FALSE(w.camera_missing);
}

TEST_CASE("fc_link counts lost messages from seq, survives noise, and restarts with the app") {
  fc_link_t l;
  fc_link_init(&l);
  feed(&l, track(0, CTP_STATE_TRACKING, true, 2000), 0);
  feed(&l, track(4, CTP_STATE_TRACKING, true, 2000), 33);  // 1, 2, 3 lost
  CHECK(l.lost == 3);
  std::vector<uint8_t> noisy = track(5, CTP_STATE_TRACKING, true, 2100);
  noisy[6] ^= 0x10u;  // a flipped bit: the CRC drops the frame
  feed(&l, noisy, 66);
  feed(&l, {0x13, 0x37, 0x00}, 70);  // garbage up to a delimiter
  feed(&l, track(6, CTP_STATE_TRACKING, true, 2200), 100);
  CHECK(l.lost == 4);  // 5 was lost to the noise
  int32_t c[3];
  REQUIRE(fc_link_target(&l, 100, c));
  CHECK(c[2] == 2200);
  CHECK(l.dec.stats.crc + l.dec.stats.framing == 2);
  feed(&l, heartbeat(0, 0), 200);  // the app restarted
  feed(&l, heartbeat(1, 0), 1200);
  CHECK(l.lost == 4);
}

TEST_CASE("fc_link's commands are what the device parses, each with a new id") {
  fc_link_t l;
  fc_link_init(&l);
  uint8_t w[CTP_MAX_WIRE];
  const size_t n = fc_link_start(&l, 100, 80, 40, 60, w, sizeof w);
  // The protocol's worked example: START id 1 at (100, 80, 40, 60).
  const uint8_t expected[] = {0x04, 0x01, 0x10, 0x01, 0x02, 0x64, 0x02, 0x50,
                              0x02, 0x28, 0x02, 0x3C, 0x03, 0xC0, 0xBD, 0x00};
  REQUIRE(n == sizeof expected);
  CHECK(std::memcmp(w, expected, n) == 0);
  const size_t m = fc_link_stop(&l, w, sizeof w);
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  ctp_frame_t f;
  int got = 0;
  for (size_t i = 0; i < m; ++i) got += ctp_decoder_push(&d, w[i], &f, nullptr) == CTP_PUSH_FRAME;
  REQUIRE(got == 1);
  ctp_command_t c;
  REQUIRE(ctp_parse_command(&f, &c) == CTP_OK);
  CHECK(c.type == CTP_CMD_STOP);
  CHECK(c.id == 2);
}
