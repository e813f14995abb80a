// The C protocol core: byte layout, CRC, COBS framing, resync, truncation, limits.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cstring>
#include <random>
#include <vector>

#include "AllocCounter.hpp"
#include "cuetrack_proto.h"

namespace {

struct Decoded {
  std::vector<ctp_frame_t> frames;
  std::vector<int> errors;
};

Decoded feed(ctp_decoder_t& d, const uint8_t* bytes, size_t n) {
  Decoded out;
  for (size_t i = 0; i < n; ++i) {
    ctp_frame_t f;
    int err = 0;
    const int r = ctp_decoder_push(&d, bytes[i], &f, &err);
    if (r == CTP_PUSH_FRAME) out.frames.push_back(f);
    if (r == CTP_PUSH_ERROR) out.errors.push_back(err);
  }
  return out;
}

ctp_track_t sampleTrack(uint32_t seq) {
  ctp_track_t t{};
  t.seq = seq;
  t.time_us = 0x0102030405060708ull + seq;
  t.state = CTP_STATE_TRACKING;
  t.flags = CTP_FLAG_HAS_3D | CTP_FLAG_LEARNED;
  t.box_px[0] = -12;
  t.box_px[1] = 300;
  t.box_px[2] = 64;
  t.box_px[3] = 0;  // a zero byte inside the payload: COBS must carry it
  t.centre_mm[0] = -250;
  t.centre_mm[1] = 0;
  t.centre_mm[2] = 1800;
  t.confidence = 54321;
  t.proc_us = 23456;
  return t;
}

bool sameTrack(const ctp_track_t& a, const ctp_track_t& b) {
  return a.seq == b.seq && a.time_us == b.time_us && a.state == b.state && a.flags == b.flags &&
         std::memcmp(a.box_px, b.box_px, sizeof a.box_px) == 0 &&
         std::memcmp(a.centre_mm, b.centre_mm, sizeof a.centre_mm) == 0 &&
         a.confidence == b.confidence && a.proc_us == b.proc_us;
}

}  // namespace

TEST_CASE("CRC-16/CCITT-FALSE matches the standard check value") {
  const uint8_t check[] = {'1', '2', '3', '4', '5', '6', '7', '8', '9'};
  REQUIRE(ctp_crc16(check, sizeof check) == 0x29B1);
  REQUIRE(ctp_crc16(check, 0) == 0xFFFF);
}

TEST_CASE("a heartbeat encodes to the exact bytes of the spec example") {
  // docs/serial-protocol.md, "Worked example": keep the two in step.
  ctp_heartbeat_t h{};
  h.seq = 7;
  h.time_us = 1000000;
  h.state = CTP_STATE_IDLE;
  h.frames = 30;
  h.rx_errors = 0;
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_heartbeat(&h, wire, sizeof wire);
  const uint8_t expected[] = {0x04, 0x01, 0x02, 0x07, 0x01, 0x01, 0x04, 0x40, 0x42, 0x0F,
                              0x01, 0x01, 0x01, 0x01, 0x01, 0x01, 0x02, 0x1E, 0x01, 0x01,
                              0x01, 0x01, 0x01, 0x01, 0x03, 0x56, 0x7B, 0x00};
  REQUIRE(n == sizeof expected);
  REQUIRE(std::memcmp(wire, expected, n) == 0);
}

TEST_CASE("every message type survives encode -> decode -> parse") {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  uint8_t wire[CTP_MAX_WIRE];
  ctp_message_t m;

  SECTION("track") {
    const ctp_track_t t = sampleTrack(41);
    const size_t n = ctp_encode_track(&t, wire, sizeof wire);
    REQUIRE(n == CTP_LEN_TRACK + 6);
    REQUIRE(std::count(wire, wire + n, 0) == 1);  // only the delimiter
    REQUIRE(wire[n - 1] == 0);
    Decoded r = feed(d, wire, n);
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.frames[0].type == CTP_MSG_TRACK);
    REQUIRE(ctp_parse_message(&r.frames[0], &m) == CTP_OK);
    REQUIRE(sameTrack(m.u.track, t));
  }
  SECTION("heartbeat, ack, error") {
    ctp_heartbeat_t h{9, 123456789ull, CTP_STATE_SEARCHING, 77, 3, CTP_HB_NO_CAMERA};
    ctp_ack_t a{10, CTP_CMD_START, 0xBEEF};
    ctp_error_t e{11, CTP_CMD_SET_RATE, 513, CTP_E_VALUE};
    std::vector<uint8_t> stream;
    size_t n = ctp_encode_heartbeat(&h, wire, sizeof wire);
    stream.insert(stream.end(), wire, wire + n);
    n = ctp_encode_ack(&a, wire, sizeof wire);
    stream.insert(stream.end(), wire, wire + n);
    n = ctp_encode_error(&e, wire, sizeof wire);
    stream.insert(stream.end(), wire, wire + n);
    Decoded r = feed(d, stream.data(), stream.size());
    REQUIRE(r.errors.empty());
    REQUIRE(r.frames.size() == 3);
    REQUIRE(ctp_parse_message(&r.frames[0], &m) == CTP_OK);
    CHECK(m.u.heartbeat.seq == 9);
    CHECK(m.u.heartbeat.time_us == 123456789ull);
    CHECK(m.u.heartbeat.state == CTP_STATE_SEARCHING);
    CHECK(m.u.heartbeat.flags == CTP_HB_NO_CAMERA);
    CHECK(m.u.heartbeat.frames == 77);
    CHECK(m.u.heartbeat.rx_errors == 3);
    REQUIRE(ctp_parse_message(&r.frames[1], &m) == CTP_OK);
    CHECK(m.u.ack.seq == 10);
    CHECK(m.u.ack.cmd_type == CTP_CMD_START);
    CHECK(m.u.ack.cmd_id == 0xBEEF);
    REQUIRE(ctp_parse_message(&r.frames[2], &m) == CTP_OK);
    CHECK(m.u.error.cmd_type == CTP_CMD_SET_RATE);
    CHECK(m.u.error.cmd_id == 513);
    CHECK(m.u.error.code == CTP_E_VALUE);
  }
  SECTION("commands") {
    ctp_command_t cmds[4] = {};
    cmds[0].type = CTP_CMD_START;
    cmds[0].id = 1;
    cmds[0].box_px[0] = 100;
    cmds[0].box_px[1] = -5;
    cmds[0].box_px[2] = 40;
    cmds[0].box_px[3] = 256;
    cmds[1].type = CTP_CMD_RESET;
    cmds[1].id = 2;
    cmds[2].type = CTP_CMD_STOP;
    cmds[2].id = 3;
    cmds[3].type = CTP_CMD_SET_RATE;
    cmds[3].id = 4;
    cmds[3].rate_hz = 15;
    for (const ctp_command_t& c : cmds) {
      const size_t n = ctp_encode_command(&c, wire, sizeof wire);
      REQUIRE(n > 0);
      Decoded r = feed(d, wire, n);
      REQUIRE(r.frames.size() == 1);
      ctp_command_t back;
      REQUIRE(ctp_parse_command(&r.frames[0], &back) == CTP_OK);
      CHECK(back.type == c.type);
      CHECK(back.id == c.id);
      CHECK(std::memcmp(back.box_px, c.box_px, sizeof c.box_px) == 0);
      CHECK(back.rate_hz == c.rate_hz);
    }
  }
}

TEST_CASE("a flipped bit anywhere in a frame is rejected as CRC or framing error") {
  const ctp_track_t t = sampleTrack(5);
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_track(&t, wire, sizeof wire);
  int rejected = 0;
  for (size_t byte = 0; byte + 1 < n; ++byte) {
    for (int bit = 0; bit < 8; ++bit) {
      uint8_t bad[CTP_MAX_WIRE];
      std::memcpy(bad, wire, n);
      bad[byte] ^= static_cast<uint8_t>(1u << bit);
      ctp_decoder_t d;
      ctp_decoder_init(&d);
      Decoded r = feed(d, bad, n);
      // A flip to 0x00 splits the frame in two: both halves must be rejected.
      REQUIRE(r.frames.empty());
      REQUIRE(!r.errors.empty());
      ++rejected;
    }
  }
  REQUIRE(rejected == static_cast<int>((n - 1) * 8));
}

TEST_CASE("the decoder resynchronises after garbage, truncation and overlong runs") {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  uint8_t wire[CTP_MAX_WIRE];
  const ctp_track_t t1 = sampleTrack(1), t2 = sampleTrack(2);
  const size_t n1 = ctp_encode_track(&t1, wire, sizeof wire);
  std::vector<uint8_t> good1(wire, wire + n1);
  const size_t n2 = ctp_encode_track(&t2, wire, sizeof wire);
  std::vector<uint8_t> good2(wire, wire + n2);

  SECTION("random garbage between frames") {
    std::mt19937 rng(1234);
    std::vector<uint8_t> s = {0x13, 0x37, 0xFF, 0x00, 0x05, 0x01, 0x02, 0x00};
    s.insert(s.end(), good1.begin(), good1.end());
    for (int i = 0; i < 500; ++i) s.push_back(static_cast<uint8_t>(rng() % 256));
    s.push_back(0x00);  // the sender's next frame starts after a delimiter
    s.insert(s.end(), good2.begin(), good2.end());
    Decoded r = feed(d, s.data(), s.size());
    REQUIRE(r.frames.size() == 2);
    ctp_message_t m;
    REQUIRE(ctp_parse_message(&r.frames[1], &m) == CTP_OK);
    REQUIRE(sameTrack(m.u.track, t2));
    REQUIRE(!r.errors.empty());
    REQUIRE(d.stats.frames == 2);
    REQUIRE(d.stats.crc + d.stats.framing + d.stats.overlong == r.errors.size());
  }
  SECTION("a truncated frame costs itself and nothing after it") {
    std::vector<uint8_t> s(good1.begin(), good1.begin() + 20);  // cut mid-frame...
    s.push_back(0x00);                                          // ...then the line recovers
    s.insert(s.end(), good2.begin(), good2.end());
    Decoded r = feed(d, s.data(), s.size());
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.errors.size() == 1);
    ctp_message_t m;
    REQUIRE(ctp_parse_message(&r.frames[0], &m) == CTP_OK);
    REQUIRE(m.u.track.seq == 2);
  }
  SECTION("a truncated frame without a delimiter corrupts only the next one") {
    std::vector<uint8_t> s(good1.begin(), good1.begin() + 20);
    s.insert(s.end(), good2.begin(), good2.end());
    s.insert(s.end(), good1.begin(), good1.end());
    Decoded r = feed(d, s.data(), s.size());
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.errors.size() == 1);
  }
  SECTION("an overlong run of non-zero bytes is dropped once, then frames flow") {
    std::vector<uint8_t> s(1000, 0x55);
    s.push_back(0x00);
    s.insert(s.end(), good1.begin(), good1.end());
    Decoded r = feed(d, s.data(), s.size());
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.errors.size() == 1);
    REQUIRE(d.stats.overlong == 1);
  }
  SECTION("empty frames (repeated delimiters) are not errors") {
    std::vector<uint8_t> s = {0, 0, 0};
    s.insert(s.end(), good1.begin(), good1.end());
    Decoded r = feed(d, s.data(), s.size());
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.errors.empty());
  }
}

TEST_CASE("frames of an unknown version or a wrong length are refused") {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  // Hand-built version-2 frame with a valid CRC.
  uint8_t raw[6] = {2, CTP_MSG_ACK, 0xAA, 0xBB, 0, 0};
  const uint16_t crc = ctp_crc16(raw, 4);
  raw[4] = static_cast<uint8_t>(crc);
  raw[5] = static_cast<uint8_t>(crc >> 8);
  // COBS by hand (no zeros in raw unless the CRC has one: check).
  REQUIRE(std::count(raw, raw + 6, 0) == 0);
  const uint8_t wire[8] = {7, raw[0], raw[1], raw[2], raw[3], raw[4], raw[5], 0};
  Decoded r = feed(d, wire, sizeof wire);
  REQUIRE(r.frames.empty());
  REQUIRE(r.errors == std::vector<int>{CTP_E_VERSION});

  // Wrong lengths at parse level.
  ctp_frame_t f{};
  f.version = CTP_VERSION;
  f.type = CTP_MSG_TRACK;
  f.len = CTP_LEN_TRACK - 1;
  ctp_message_t m;
  REQUIRE(ctp_parse_message(&f, &m) == CTP_E_LENGTH);
  f.type = 0x7E;
  REQUIRE(ctp_parse_message(&f, &m) == CTP_E_TYPE);
  ctp_command_t c;
  f.type = CTP_CMD_START;
  f.len = 4;
  f.payload[0] = 0x34;
  f.payload[1] = 0x12;
  REQUIRE(ctp_parse_command(&f, &c) == CTP_E_LENGTH);
  CHECK(c.type == CTP_CMD_START);
  CHECK(c.id == 0x1234);  // known, so the ERROR reply can name it
  f.type = CTP_MSG_TRACK;
  REQUIRE(ctp_parse_command(&f, &c) == CTP_E_TYPE);
}

TEST_CASE("command values out of range are refused with bad-value") {
  ctp_command_t c{};
  c.type = CTP_CMD_START;
  c.id = 5;
  c.box_px[2] = 0;
  c.box_px[3] = 10;
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_command(&c, wire, sizeof wire);
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  Decoded r = feed(d, wire, n);
  REQUIRE(r.frames.size() == 1);
  ctp_command_t back;
  REQUIRE(ctp_parse_command(&r.frames[0], &back) == CTP_E_VALUE);
  REQUIRE(back.id == 5);

  c.type = CTP_CMD_SET_RATE;
  c.rate_hz = 1001;
  const size_t n2 = ctp_encode_command(&c, wire, sizeof wire);
  r = feed(d, wire, n2);
  REQUIRE(ctp_parse_command(&r.frames[0], &back) == CTP_E_VALUE);
}

TEST_CASE("encoding refuses buffers that are too small instead of overrunning") {
  const ctp_track_t t = sampleTrack(3);
  uint8_t wire[CTP_MAX_WIRE];
  REQUIRE(ctp_encode_track(&t, wire, CTP_LEN_TRACK + 5) == 0);
  REQUIRE(ctp_encode_track(&t, wire, CTP_LEN_TRACK + 6) == CTP_LEN_TRACK + 6);
  uint8_t big[CTP_MAX_PAYLOAD + 1] = {};
  REQUIRE(ctp_encode_frame(0x20, big, sizeof big, wire, sizeof wire) == 0);
  REQUIRE(ctp_encode_frame(0x20, big, CTP_MAX_PAYLOAD, wire, sizeof wire) == CTP_MAX_WIRE);
}

TEST_CASE("encoding and decoding never allocate") {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  const ctp_track_t t = sampleTrack(8);
  uint8_t wire[CTP_MAX_WIRE];
  int frames = 0;
  {
    cuetrack::test::AllocScope scope;
    for (int i = 0; i < 100; ++i) {
      const size_t n = ctp_encode_track(&t, wire, sizeof wire);
      for (size_t k = 0; k < n; ++k) {
        ctp_frame_t f;
        if (ctp_decoder_push(&d, wire[k], &f, nullptr) == CTP_PUSH_FRAME) ++frames;
      }
    }
    REQUIRE(scope.allocations() == 0);
  }
  REQUIRE(frames == 100);
  cuetrack::test::AllocScope control;  // positive control: the counter does see allocations
  std::vector<int>* v = new std::vector<int>(3);
  delete v;
  REQUIRE(control.allocations() >= 1);
}

TEST_CASE("a START command encodes to the exact bytes of the spec example") {
  ctp_command_t c{};
  c.type = CTP_CMD_START;
  c.id = 1;
  c.box_px[0] = 100;
  c.box_px[1] = 80;
  c.box_px[2] = 40;
  c.box_px[3] = 60;
  uint8_t wire[CTP_MAX_WIRE];
  const size_t n = ctp_encode_command(&c, wire, sizeof wire);
  const uint8_t expected[] = {0x04, 0x01, 0x10, 0x01, 0x02, 0x64, 0x02, 0x50,
                              0x02, 0x28, 0x02, 0x3C, 0x03, 0xC0, 0xBD, 0x00};
  REQUIRE(n == sizeof expected);
  REQUIRE(std::memcmp(wire, expected, n) == 0);
}

TEST_CASE("the largest frame decodes, one byte more is overlong") {
  for (uint8_t fill : {uint8_t{0x00}, uint8_t{0xFF}, uint8_t{0x01}}) {
    uint8_t payload[CTP_MAX_PAYLOAD];
    std::memset(payload, fill, sizeof payload);
    uint8_t wire[CTP_MAX_WIRE];
    const size_t n = ctp_encode_frame(0x20, payload, sizeof payload, wire, sizeof wire);
    REQUIRE(n == CTP_MAX_WIRE);
    ctp_decoder_t d;
    ctp_decoder_init(&d);
    Decoded r = feed(d, wire, n);
    REQUIRE(r.frames.size() == 1);
    REQUIRE(r.frames[0].len == CTP_MAX_PAYLOAD);
    REQUIRE(std::memcmp(r.frames[0].payload, payload, sizeof payload) == 0);
  }
  std::vector<uint8_t> tooLong(CTP_MAX_ENCODED + 1, 0x01);
  tooLong.push_back(0);
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  Decoded r = feed(d, tooLong.data(), tooLong.size());
  REQUIRE(r.frames.empty());
  REQUIRE(d.stats.overlong == 1);
}
