// Any bytes into the protocol decoder: no crash, no overrun, and every frame it
// accepts as a valid device message re-encodes to the identical wire bytes.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "cuetrack_proto.h"

namespace {

size_t reencode(const ctp_message_t& m, uint8_t* out, size_t cap) {
  switch (m.type) {
    case CTP_MSG_TRACK:
      return ctp_encode_track(&m.u.track, out, cap);
    case CTP_MSG_HEARTBEAT:
      return ctp_encode_heartbeat(&m.u.heartbeat, out, cap);
    case CTP_MSG_ACK:
      return ctp_encode_ack(&m.u.ack, out, cap);
    case CTP_MSG_ERROR:
      return ctp_encode_error(&m.u.error, out, cap);
    default:
      return 0;
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  ctp_decoder_t d;
  ctp_decoder_init(&d);
  uint32_t frames = 0, errors = 0;
  for (size_t i = 0; i < size; ++i) {
    ctp_frame_t f;
    int err = 0;
    const int r = ctp_decoder_push(&d, data[i], &f, &err);
    if (r == CTP_PUSH_ERROR) {
      ++errors;
      if (err != CTP_E_CRC && err != CTP_E_FRAMING && err != CTP_E_VERSION) abort();
      continue;
    }
    if (r != CTP_PUSH_FRAME) continue;
    ++frames;
    if (f.len > CTP_MAX_PAYLOAD || f.version != CTP_VERSION) abort();
    ctp_message_t m;
    if (ctp_parse_message(&f, &m) != CTP_OK) continue;
    // Heartbeat's reserved byte is not kept: only compare when it was 0.
    if (m.type == CTP_MSG_HEARTBEAT && f.payload[13] != 0) continue;
    uint8_t again[CTP_MAX_WIRE];
    const size_t n = reencode(m, again, sizeof again);
    ctp_decoder_t d2;
    ctp_decoder_init(&d2);
    ctp_frame_t f2{};
    int got = CTP_PUSH_NONE;
    for (size_t k = 0; k < n; ++k) got = ctp_decoder_push(&d2, again[k], &f2, nullptr);
    if (got != CTP_PUSH_FRAME || f2.type != f.type || f2.len != f.len ||
        std::memcmp(f2.payload, f.payload, f.len) != 0) {
      abort();
    }
  }
  const ctp_stats_t& s = d.stats;
  if (s.frames != frames || s.crc + s.framing + s.overlong + s.version != errors) abort();
  return 0;
}
