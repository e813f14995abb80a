/* cuetrack serial protocol v1: see cuetrack_proto.h and docs/serial-protocol.md. */
#include "cuetrack_proto.h"

#include <string.h>

/* ---- little-endian field access (no unaligned loads: portable to any MCU) ---- */
static void put16(uint8_t* p, uint16_t v) {
  p[0] = (uint8_t)v;
  p[1] = (uint8_t)(v >> 8);
}
static void put32(uint8_t* p, uint32_t v) {
  put16(p, (uint16_t)v);
  put16(p + 2, (uint16_t)(v >> 16));
}
static void put64(uint8_t* p, uint64_t v) {
  put32(p, (uint32_t)v);
  put32(p + 4, (uint32_t)(v >> 32));
}
static uint16_t get16(const uint8_t* p) {
  return (uint16_t)(p[0] | (p[1] << 8));
}
static uint32_t get32(const uint8_t* p) {
  return (uint32_t)get16(p) | ((uint32_t)get16(p + 2) << 16);
}
static uint64_t get64(const uint8_t* p) {
  return (uint64_t)get32(p) | ((uint64_t)get32(p + 4) << 32);
}

/* CRC-16/CCITT-FALSE: poly 0x1021, init 0xFFFF, no reflection, no final xor.
 * Bitwise on purpose: no 512-byte table on small parts; 68 bytes cost ~600 shifts. */
uint16_t ctp_crc16(const uint8_t* data, size_t len) {
  uint16_t crc = 0xFFFFu;
  for (size_t i = 0; i < len; ++i) {
    crc ^= (uint16_t)((uint16_t)data[i] << 8);
    for (int b = 0; b < 8; ++b) {
      crc = (crc & 0x8000u) ? (uint16_t)(((unsigned)crc << 1) ^ 0x1021u)
                            : (uint16_t)((unsigned)crc << 1);
    }
  }
  return crc;
}

/* ---- COBS ---- */
static size_t cobs_encode(const uint8_t* in, size_t len, uint8_t* out) {
  size_t codePos = 0, o = 1;
  uint8_t code = 1;
  for (size_t i = 0; i < len; ++i) {
    if (in[i] == 0) {
      out[codePos] = code;
      codePos = o++;
      code = 1;
    } else {
      out[o++] = in[i];
      if (++code == 0xFF) {
        out[codePos] = code;
        codePos = o++;
        code = 1;
      }
    }
  }
  out[codePos] = code;
  return o;
}

/* Returns the decoded length, or -1 for invalid COBS / output over cap. */
static int cobs_decode(const uint8_t* in, size_t len, uint8_t* out, size_t cap) {
  size_t i = 0, o = 0;
  while (i < len) {
    const uint8_t code = in[i++];
    if (code == 0 || i + (size_t)code - 1 > len) return -1;
    for (uint8_t j = 1; j < code; ++j) {
      if (o >= cap) return -1;
      out[o++] = in[i++];
    }
    if (code != 0xFF && i < len) {
      if (o >= cap) return -1;
      out[o++] = 0;
    }
  }
  return (int)o;
}

/* ---- decoder ---- */
void ctp_decoder_init(ctp_decoder_t* d) {
  memset(d, 0, sizeof(*d));
}

static int finish_frame(ctp_decoder_t* d, ctp_frame_t* out, int* err) {
  uint8_t raw[CTP_MAX_RAW];
  const int n = cobs_decode(d->buf, d->len, raw, sizeof raw);
  d->len = 0;
  if (n < 4) {
    d->stats.framing++;
    *err = CTP_E_FRAMING;
    return CTP_PUSH_ERROR;
  }
  const uint16_t crc = get16(raw + n - 2);
  if (ctp_crc16(raw, (size_t)n - 2) != crc) {
    d->stats.crc++;
    *err = CTP_E_CRC;
    return CTP_PUSH_ERROR;
  }
  if (raw[0] != CTP_VERSION) {
    d->stats.version++;
    *err = CTP_E_VERSION;
    return CTP_PUSH_ERROR;
  }
  out->version = raw[0];
  out->type = raw[1];
  out->len = (uint8_t)(n - 4);
  memcpy(out->payload, raw + 2, (size_t)n - 4);
  d->stats.frames++;
  return CTP_PUSH_FRAME;
}

int ctp_decoder_push(ctp_decoder_t* d, uint8_t byte, ctp_frame_t* out, int* err) {
  int dummy = 0;
  if (!err) err = &dummy;
  if (byte != 0) {
    if (d->overflow) return CTP_PUSH_NONE;
    if (d->len >= CTP_MAX_ENCODED) {
      d->overflow = 1;
      d->len = 0;
      d->stats.overlong++;
      *err = CTP_E_FRAMING;
      return CTP_PUSH_ERROR;
    }
    d->buf[d->len++] = byte;
    return CTP_PUSH_NONE;
  }
  /* Delimiter: an empty frame (0x00 0x00) is a harmless resync, not an error. */
  if (d->overflow) {
    d->overflow = 0;
    return CTP_PUSH_NONE;
  }
  if (d->len == 0) return CTP_PUSH_NONE;
  return finish_frame(d, out, err);
}

/* ---- encoding ---- */
size_t ctp_encode_frame(uint8_t type, const uint8_t* payload, size_t len, uint8_t* out,
                        size_t cap) {
  uint8_t raw[CTP_MAX_RAW];
  if (len > CTP_MAX_PAYLOAD || cap < len + 4 + 2) return 0;
  raw[0] = CTP_VERSION;
  raw[1] = type;
  if (len) memcpy(raw + 2, payload, len);
  put16(raw + 2 + len, ctp_crc16(raw, len + 2));
  const size_t n = cobs_encode(raw, len + 4, out);
  out[n] = 0;
  return n + 1;
}

size_t ctp_encode_track(const ctp_track_t* m, uint8_t* out, size_t cap) {
  uint8_t p[CTP_LEN_TRACK];
  put32(p, m->seq);
  put64(p + 4, m->time_us);
  p[12] = m->state;
  p[13] = m->flags;
  for (int i = 0; i < 4; ++i) put16(p + 14 + 2 * i, (uint16_t)m->box_px[i]);
  for (int i = 0; i < 3; ++i) put32(p + 22 + 4 * i, (uint32_t)m->centre_mm[i]);
  put16(p + 34, m->confidence);
  put32(p + 36, m->proc_us);
  return ctp_encode_frame(CTP_MSG_TRACK, p, sizeof p, out, cap);
}

size_t ctp_encode_heartbeat(const ctp_heartbeat_t* m, uint8_t* out, size_t cap) {
  uint8_t p[CTP_LEN_HEARTBEAT];
  put32(p, m->seq);
  put64(p + 4, m->time_us);
  p[12] = m->state;
  p[13] = m->flags;
  put32(p + 14, m->frames);
  put32(p + 18, m->rx_errors);
  return ctp_encode_frame(CTP_MSG_HEARTBEAT, p, sizeof p, out, cap);
}

size_t ctp_encode_ack(const ctp_ack_t* m, uint8_t* out, size_t cap) {
  uint8_t p[CTP_LEN_ACK];
  put32(p, m->seq);
  p[4] = m->cmd_type;
  put16(p + 5, m->cmd_id);
  return ctp_encode_frame(CTP_MSG_ACK, p, sizeof p, out, cap);
}

size_t ctp_encode_error(const ctp_error_t* m, uint8_t* out, size_t cap) {
  uint8_t p[CTP_LEN_ERROR];
  put32(p, m->seq);
  p[4] = m->cmd_type;
  put16(p + 5, m->cmd_id);
  p[7] = m->code;
  return ctp_encode_frame(CTP_MSG_ERROR, p, sizeof p, out, cap);
}

static int command_len(uint8_t type) {
  switch (type) {
    case CTP_CMD_START:
      return CTP_LEN_START;
    case CTP_CMD_RESET:
      return CTP_LEN_RESET;
    case CTP_CMD_STOP:
      return CTP_LEN_STOP;
    case CTP_CMD_SET_RATE:
      return CTP_LEN_SET_RATE;
    default:
      return -1;
  }
}

size_t ctp_encode_command(const ctp_command_t* c, uint8_t* out, size_t cap) {
  uint8_t p[CTP_LEN_START];
  const int len = command_len(c->type);
  if (len < 0) return 0;
  put16(p, c->id);
  if (c->type == CTP_CMD_START) {
    for (int i = 0; i < 4; ++i) put16(p + 2 + 2 * i, (uint16_t)c->box_px[i]);
  } else if (c->type == CTP_CMD_SET_RATE) {
    put16(p + 2, c->rate_hz);
  }
  return ctp_encode_frame(c->type, p, (size_t)len, out, cap);
}

/* ---- parsing ---- */
int ctp_parse_message(const ctp_frame_t* f, ctp_message_t* out) {
  const uint8_t* p = f->payload;
  memset(out, 0, sizeof(*out));
  out->type = f->type;
  switch (f->type) {
    case CTP_MSG_TRACK: {
      ctp_track_t* m = &out->u.track;
      if (f->len != CTP_LEN_TRACK) return CTP_E_LENGTH;
      m->seq = get32(p);
      m->time_us = get64(p + 4);
      m->state = p[12];
      m->flags = p[13];
      for (int i = 0; i < 4; ++i) m->box_px[i] = (int16_t)get16(p + 14 + 2 * i);
      for (int i = 0; i < 3; ++i) m->centre_mm[i] = (int32_t)get32(p + 22 + 4 * i);
      m->confidence = get16(p + 34);
      m->proc_us = get32(p + 36);
      return m->state > CTP_STATE_SEARCHING ? CTP_E_VALUE : CTP_OK;
    }
    case CTP_MSG_HEARTBEAT: {
      ctp_heartbeat_t* m = &out->u.heartbeat;
      if (f->len != CTP_LEN_HEARTBEAT) return CTP_E_LENGTH;
      m->seq = get32(p);
      m->time_us = get64(p + 4);
      m->state = p[12];
      m->flags = p[13];
      m->frames = get32(p + 14);
      m->rx_errors = get32(p + 18);
      return m->state > CTP_STATE_SEARCHING ? CTP_E_VALUE : CTP_OK;
    }
    case CTP_MSG_ACK:
      if (f->len != CTP_LEN_ACK) return CTP_E_LENGTH;
      out->u.ack.seq = get32(p);
      out->u.ack.cmd_type = p[4];
      out->u.ack.cmd_id = get16(p + 5);
      return CTP_OK;
    case CTP_MSG_ERROR:
      if (f->len != CTP_LEN_ERROR) return CTP_E_LENGTH;
      out->u.error.seq = get32(p);
      out->u.error.cmd_type = p[4];
      out->u.error.cmd_id = get16(p + 5);
      out->u.error.code = p[7];
      return CTP_OK;
    default:
      return CTP_E_TYPE;
  }
}

int ctp_parse_command(const ctp_frame_t* f, ctp_command_t* out) {
  const uint8_t* p = f->payload;
  const int len = command_len(f->type);
  memset(out, 0, sizeof(*out));
  if (len < 0) return CTP_E_TYPE;
  out->type = f->type;
  if (f->len >= 2) out->id = get16(p);
  if (f->len != len) return CTP_E_LENGTH;
  if (f->type == CTP_CMD_START) {
    for (int i = 0; i < 4; ++i) out->box_px[i] = (int16_t)get16(p + 2 + 2 * i);
    if (out->box_px[2] <= 0 || out->box_px[3] <= 0) return CTP_E_VALUE;
  } else if (f->type == CTP_CMD_SET_RATE) {
    out->rate_hz = get16(p + 2);
    if (out->rate_hz > 1000) return CTP_E_VALUE;
  }
  return CTP_OK;
}

const char* ctp_error_name(int code) {
  switch (code) {
    case CTP_OK:
      return "ok";
    case CTP_E_CRC:
      return "bad-crc";
    case CTP_E_LENGTH:
      return "bad-length";
    case CTP_E_TYPE:
      return "unknown-type";
    case CTP_E_VERSION:
      return "bad-version";
    case CTP_E_VALUE:
      return "bad-value";
    case CTP_E_REJECTED:
      return "rejected";
    case CTP_E_FRAMING:
      return "bad-framing";
    case CTP_E_BUSY:
      return "busy";
    default:
      return "unknown-error";
  }
}

const char* ctp_state_name(uint8_t state) {
  switch (state) {
    case CTP_STATE_IDLE:
      return "idle";
    case CTP_STATE_TRACKING:
      return "tracking";
    case CTP_STATE_LOST:
      return "lost";
    case CTP_STATE_SEARCHING:
      return "searching";
    default:
      return "invalid";
  }
}

const char* ctp_type_name(uint8_t type) {
  switch (type) {
    case CTP_MSG_TRACK:
      return "track";
    case CTP_MSG_HEARTBEAT:
      return "heartbeat";
    case CTP_MSG_ACK:
      return "ack";
    case CTP_MSG_ERROR:
      return "error";
    case CTP_CMD_START:
      return "start";
    case CTP_CMD_RESET:
      return "reset";
    case CTP_CMD_STOP:
      return "stop";
    case CTP_CMD_SET_RATE:
      return "rate";
    default:
      return "unknown";
  }
}
