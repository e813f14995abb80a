#include "fc_link.h"

#include <string.h>

void fc_link_init(fc_link_t* l) {
  memset(l, 0, sizeof *l);
  ctp_decoder_init(&l->dec);
  l->next_id = 1;
}

/* Every device message carries seq: a jump forward counts the messages lost; a jump
 * back means the app restarted (at 0), and counting starts again from there. */
static void note_seq(fc_link_t* l, uint32_t seq) {
  if (l->have_seq && seq > l->next_seq) l->lost += seq - l->next_seq;
  l->have_seq = 1;
  l->next_seq = seq + 1u;
}

void fc_link_on_byte(fc_link_t* l, uint8_t byte, uint32_t now_ms) {
  ctp_frame_t f;
  ctp_message_t m;
  if (ctp_decoder_push(&l->dec, byte, &f, NULL) != CTP_PUSH_FRAME) return;
  if (ctp_parse_message(&f, &m) != CTP_OK) return; /* not for us (a command echo, noise) */
  l->rx_ms = now_ms;
  l->heard = 1;
  switch (m.type) {
    case CTP_MSG_TRACK:
      note_seq(l, m.u.track.seq);
      l->track = m.u.track;
      l->track_ms = now_ms;
      l->have_track = 1;
      l->camera_missing = 0; /* frames flow */
      break;
    case CTP_MSG_HEARTBEAT:
      note_seq(l, m.u.heartbeat.seq);
      l->camera_missing = (uint8_t)((m.u.heartbeat.flags & CTP_HB_NO_CAMERA) != 0u);
      break;
    case CTP_MSG_ACK:
      note_seq(l, m.u.ack.seq);
      ++l->acks;
      break;
    case CTP_MSG_ERROR:
      note_seq(l, m.u.error.seq);
      ++l->errors;
      break;
    default:
      break;
  }
}

int fc_link_alive(const fc_link_t* l, uint32_t now_ms) {
  return l->heard && (uint32_t)(now_ms - l->rx_ms) < FC_LINK_DEAD_MS; /* wraps safely */
}

int fc_link_target(const fc_link_t* l, uint32_t now_ms, int32_t centre_mm[3]) {
  if (!l->have_track || (uint32_t)(now_ms - l->track_ms) >= FC_LINK_FRESH_MS) return 0;
  if (l->track.state != CTP_STATE_TRACKING || (l->track.flags & CTP_FLAG_HAS_3D) == 0u) return 0;
  centre_mm[0] = l->track.centre_mm[0];
  centre_mm[1] = l->track.centre_mm[1];
  centre_mm[2] = l->track.centre_mm[2];
  return 1;
}

static size_t encode_command(fc_link_t* l, ctp_command_t* c, uint8_t* out, size_t cap) {
  c->id = l->next_id++;
  return ctp_encode_command(c, out, cap);
}

size_t fc_link_start(fc_link_t* l, int16_t x, int16_t y, int16_t w, int16_t h, uint8_t* out,
                     size_t cap) {
  ctp_command_t c;
  memset(&c, 0, sizeof c);
  c.type = CTP_CMD_START;
  c.box_px[0] = x;
  c.box_px[1] = y;
  c.box_px[2] = w;
  c.box_px[3] = h;
  return encode_command(l, &c, out, cap);
}

size_t fc_link_stop(fc_link_t* l, uint8_t* out, size_t cap) {
  ctp_command_t c;
  memset(&c, 0, sizeof c);
  c.type = CTP_CMD_STOP;
  return encode_command(l, &c, out, cap);
}
