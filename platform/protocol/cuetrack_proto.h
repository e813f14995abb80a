/* cuetrack serial protocol, version 1: encoder and decoder.
 *
 * Plain C11, no allocation, no global state, no OS calls: copy this header and
 * cuetrack_proto.c verbatim into a microcontroller project. The byte-level
 * specification is docs/serial-protocol.md; this file follows it.
 *
 * Frame on the wire:  COBS( version | type | payload | crc16_le ) 0x00
 * All multi-byte fields little-endian. CRC-16/CCITT-FALSE over version..payload.
 *
 * Memory: ctp_decoder_t is CTP_MAX_ENCODED + 23 bytes (92 B); nothing else is kept.
 */
#ifndef CUETRACK_PROTO_H
#define CUETRACK_PROTO_H

#include <stddef.h>
#include <stdint.h>

#ifdef __cplusplus
extern "C" {
#endif

#define CTP_VERSION 1u
#define CTP_MAX_PAYLOAD 64u                     /* bytes of message body */
#define CTP_MAX_RAW (2u + CTP_MAX_PAYLOAD + 2u) /* version+type+payload+crc = 68 */
#define CTP_MAX_ENCODED (CTP_MAX_RAW + 1u)      /* COBS adds one byte below 254 */
#define CTP_MAX_WIRE (CTP_MAX_ENCODED + 1u)     /* plus the 0x00 delimiter = 70 */

/* Message types. 0x01..0x0F device -> host, 0x10..0x1F host -> device. */
enum {
  CTP_MSG_TRACK = 0x01,
  CTP_MSG_HEARTBEAT = 0x02,
  CTP_MSG_ACK = 0x03,
  CTP_MSG_ERROR = 0x04,
  CTP_CMD_START = 0x10,
  CTP_CMD_RESET = 0x11,
  CTP_CMD_STOP = 0x12,
  CTP_CMD_SET_RATE = 0x13
};

/* Payload sizes, fixed per type (a frame of another size is rejected). */
enum {
  CTP_LEN_TRACK = 40,
  CTP_LEN_HEARTBEAT = 22,
  CTP_LEN_ACK = 7,
  CTP_LEN_ERROR = 8,
  CTP_LEN_START = 10,
  CTP_LEN_RESET = 2,
  CTP_LEN_STOP = 2,
  CTP_LEN_SET_RATE = 4
};

/* Tracker state carried by TRACK and HEARTBEAT. */
enum {
  CTP_STATE_IDLE = 0,     /* no target: waiting for START */
  CTP_STATE_TRACKING = 1, /* target located */
  CTP_STATE_LOST = 2,     /* target lost in this frame */
  CTP_STATE_SEARCHING = 3 /* still lost, trying to re-acquire */
};

/* TRACK flags. */
#define CTP_FLAG_HAS_3D 0x01u  /* centre_mm valid */
#define CTP_FLAG_LEARNED 0x02u /* the model was updated with this frame */
/* TRACKING, but the target is hidden behind something nearer: box and centre_mm are where
   it was last seen (3D only) */
#define CTP_FLAG_OCCLUDED 0x04u
/* 3D: too little valid depth on the target (a black, glossy or sunlit surface, or nearer
   than the sensor's range): centre_mm's z is predicted from its motion, not measured, and
   the box was placed by colour alone */
#define CTP_FLAG_DEPTH_PREDICTED 0x08u
/* HEARTBEAT flags */
#define CTP_HB_NO_CAMERA 0x01u /* no camera yet: the device waits for one to be plugged in */

/* Error codes: in ERROR replies and as negative parse results (-code). */
enum {
  CTP_OK = 0,
  CTP_E_CRC = 1,      /* CRC mismatch */
  CTP_E_LENGTH = 2,   /* payload size wrong for its type */
  CTP_E_TYPE = 3,     /* unknown message type */
  CTP_E_VERSION = 4,  /* protocol version not supported */
  CTP_E_VALUE = 5,    /* a field out of range (e.g. box w <= 0) */
  CTP_E_REJECTED = 6, /* well-formed command that could not be applied */
  CTP_E_FRAMING = 7,  /* invalid COBS, frame too short or too long */
  CTP_E_BUSY = 8      /* command not possible in the current state */
};

typedef struct {
  uint32_t seq;         /* device message counter, shared by all device messages */
  uint64_t time_us;     /* frame capture time [us] */
  uint8_t state;        /* CTP_STATE_* */
  uint8_t flags;        /* CTP_FLAG_* */
  int16_t box_px[4];    /* x, y (top-left), w, h [px]; lost/searching: the last confirmed */
  int32_t centre_mm[3]; /* x right, y down, z forward, camera frame [mm] */
  uint16_t confidence;  /* 0..65535 = 0..1 */
  uint32_t proc_us;     /* processing time of this frame [us] */
} ctp_track_t;

typedef struct {
  uint32_t seq;
  uint64_t time_us;   /* device monotonic time [us] */
  uint8_t state;      /* CTP_STATE_* */
  uint32_t frames;    /* frames processed since start */
  uint32_t rx_errors; /* inbound frames rejected since start */
  uint8_t flags;      /* CTP_HB_* (last: older code initialising in order stays right) */
} ctp_heartbeat_t;

typedef struct {
  uint32_t seq;
  uint8_t cmd_type; /* type of the acknowledged command */
  uint16_t cmd_id;  /* its id */
} ctp_ack_t;

typedef struct {
  uint32_t seq;
  uint8_t cmd_type; /* 0 when the frame could not be read that far */
  uint16_t cmd_id;  /* 0 when unknown */
  uint8_t code;     /* CTP_E_* */
} ctp_error_t;

/* A device -> host message. */
typedef struct {
  uint8_t type; /* CTP_MSG_* */
  union {
    ctp_track_t track;
    ctp_heartbeat_t heartbeat;
    ctp_ack_t ack;
    ctp_error_t error;
  } u;
} ctp_message_t;

/* A host -> device command. */
typedef struct {
  uint8_t type;      /* CTP_CMD_* */
  uint16_t id;       /* chosen by the host, echoed in ACK/ERROR */
  int16_t box_px[4]; /* START: x, y, w, h [px] */
  uint16_t rate_hz;  /* SET_RATE: max track messages per second, 0 = every frame */
} ctp_command_t;

/* One frame after COBS decoding and CRC check. */
typedef struct {
  uint8_t version;
  uint8_t type;
  uint8_t len; /* payload bytes */
  uint8_t payload[CTP_MAX_PAYLOAD];
} ctp_frame_t;

typedef struct {
  uint32_t frames;   /* good frames delivered */
  uint32_t crc;      /* CRC mismatches */
  uint32_t framing;  /* invalid COBS or shorter than 4 bytes */
  uint32_t overlong; /* more than CTP_MAX_ENCODED bytes before a delimiter */
  uint32_t version;  /* good CRC, unsupported version */
} ctp_stats_t;

typedef struct {
  uint8_t buf[CTP_MAX_ENCODED];
  uint8_t len;
  uint8_t overflow; /* discarding until the next 0x00 */
  ctp_stats_t stats;
} ctp_decoder_t;

/* Result of ctp_decoder_push. */
enum {
  CTP_PUSH_NONE = 0,  /* byte consumed, no frame yet */
  CTP_PUSH_FRAME = 1, /* *out holds a frame */
  CTP_PUSH_ERROR = 2  /* a frame was rejected; ctp_decoder_push's *err says why */
};

uint16_t ctp_crc16(const uint8_t* data, size_t len);

void ctp_decoder_init(ctp_decoder_t* d);
/* Feed one received byte. On CTP_PUSH_FRAME *out is filled; on CTP_PUSH_ERROR
 * *err is CTP_E_CRC, CTP_E_FRAMING or CTP_E_VERSION (err may be NULL). */
int ctp_decoder_push(ctp_decoder_t* d, uint8_t byte, ctp_frame_t* out, int* err);

/* Frame a payload: writes COBS bytes plus the 0x00 delimiter. Returns bytes
 * written, or 0 when len > CTP_MAX_PAYLOAD or cap is too small
 * (CTP_MAX_WIRE is always enough). */
size_t ctp_encode_frame(uint8_t type, const uint8_t* payload, size_t len, uint8_t* out, size_t cap);

size_t ctp_encode_track(const ctp_track_t* m, uint8_t* out, size_t cap);
size_t ctp_encode_heartbeat(const ctp_heartbeat_t* m, uint8_t* out, size_t cap);
size_t ctp_encode_ack(const ctp_ack_t* m, uint8_t* out, size_t cap);
size_t ctp_encode_error(const ctp_error_t* m, uint8_t* out, size_t cap);
size_t ctp_encode_command(const ctp_command_t* c, uint8_t* out, size_t cap);

/* Parse a device -> host frame. Returns CTP_OK or a CTP_E_* code. */
int ctp_parse_message(const ctp_frame_t* f, ctp_message_t* out);
/* Parse a host -> device frame. Returns CTP_OK or a CTP_E_* code; on error
 * out->type and out->id are still set as far as the frame allowed (else 0), so
 * the device can address its ERROR reply. */
int ctp_parse_command(const ctp_frame_t* f, ctp_command_t* out);

const char* ctp_error_name(int code);
const char* ctp_state_name(uint8_t state);
const char* ctp_type_name(uint8_t type);

#ifdef __cplusplus
}
#endif

#endif /* CUETRACK_PROTO_H */
