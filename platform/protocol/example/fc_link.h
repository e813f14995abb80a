/* The flight controller's side of the cuetrack link: an example to copy into firmware
 * beside cuetrack_proto.{h,c}. Plain C, no allocation, no globals, no clock of its own
 * (the caller passes its millisecond tick).
 *
 *   fc_link_t link;  fc_link_init(&link);
 *   UART receive:    fc_link_on_byte(&link, byte, millis());
 *   control loop:    if (fc_link_target(&link, millis(), centre_mm)) steer(centre_mm);
 *                    else if (!fc_link_alive(&link, millis())) failsafe();
 *   to track a box:  n = fc_link_start(&link, x, y, w, h, buf, sizeof buf); uart_write(buf, n);
 *
 * docs/serial-protocol.md, section 9, explains the choices (freshness, health, flags). */
#ifndef CUETRACK_FC_LINK_H
#define CUETRACK_FC_LINK_H

#include <stddef.h>
#include <stdint.h>

#include "cuetrack_proto.h"

#ifdef __cplusplus
extern "C" {
#endif

#define FC_LINK_DEAD_MS 2000u /* nothing for this long: board or line gone (1 s heartbeats) */
#define FC_LINK_FRESH_MS 200u /* a TRACK older than this is not steered by */

typedef struct {
  ctp_decoder_t dec;
  ctp_track_t track;      /* the newest TRACK */
  uint32_t track_ms;      /* when it arrived */
  uint32_t rx_ms;         /* when any good message last arrived */
  uint8_t have_track;     /* a TRACK arrived since init */
  uint8_t heard;          /* any good message arrived since init */
  uint8_t camera_missing; /* the newest HEARTBEAT said: no camera yet */
  uint8_t have_seq;
  uint32_t next_seq;     /* the seq the next message should carry */
  uint32_t lost;         /* messages lost, from gaps in seq */
  uint32_t acks, errors; /* replies to our commands */
  uint16_t next_id;      /* id for our next command */
} fc_link_t;

void fc_link_init(fc_link_t* l);
/* Every byte the UART receives, with the current tick [ms]. */
void fc_link_on_byte(fc_link_t* l, uint8_t byte, uint32_t now_ms);
/* The board has been heard within FC_LINK_DEAD_MS. */
int fc_link_alive(const fc_link_t* l, uint32_t now_ms);
/* A target to steer by: the newest TRACK is fresh, tracking, and has a 3D centre.
 * Copies its centre [mm] (x right, y down, z forward, camera frame). */
int fc_link_target(const fc_link_t* l, uint32_t now_ms, int32_t centre_mm[3]);
/* Encode a command into out (CTP_MAX_WIRE bytes suffice); returns the bytes to send. */
size_t fc_link_start(fc_link_t* l, int16_t x, int16_t y, int16_t w, int16_t h, uint8_t* out,
                     size_t cap);
size_t fc_link_stop(fc_link_t* l, uint8_t* out, size_t cap);

#ifdef __cplusplus
}
#endif

#endif /* CUETRACK_FC_LINK_H */
