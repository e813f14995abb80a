// Compiled with -w: the generated headers warn under GCC 12 (their README says so).
#include "OfficialMavlink.hpp"

#include <cstring>

#include "common/mavlink.h"

namespace cuetrack::test::official {

struct Decoder::State {
  mavlink_message_t rx{};
  mavlink_status_t status{};
  mavlink_message_t msg{};
  mavlink_status_t msgStatus{};
};

Decoder::Decoder() : _s(new State) {}
Decoder::~Decoder() {
  delete _s;
}

int Decoder::push(uint8_t byte, Decoded* out) {
  const uint8_t r = mavlink_frame_char_buffer(&_s->rx, &_s->status, byte, &_s->msg, &_s->msgStatus);
  if (r == MAVLINK_FRAMING_BAD_CRC || r == MAVLINK_FRAMING_BAD_SIGNATURE) return -1;
  if (r != MAVLINK_FRAMING_OK) return 0;
  const mavlink_message_t& m = _s->msg;
  Decoded d;
  d.msgId = m.msgid;
  d.seq = m.seq;
  d.sysId = m.sysid;
  d.compId = m.compid;
  switch (m.msgid) {
    case MAVLINK_MSG_ID_HEARTBEAT: {
      mavlink_heartbeat_t h;
      mavlink_msg_heartbeat_decode(&m, &h);
      d.hbType = h.type;
      d.hbAutopilot = h.autopilot;
      d.hbSystemStatus = h.system_status;
      d.hbCustomMode = h.custom_mode;
      break;
    }
    case MAVLINK_MSG_ID_CAMERA_TRACKING_IMAGE_STATUS: {
      mavlink_camera_tracking_image_status_t s;
      mavlink_msg_camera_tracking_image_status_decode(&m, &s);
      d.trackingStatus = s.tracking_status;
      d.trackingMode = s.tracking_mode;
      d.targetData = s.target_data;
      d.pointX = s.point_x;
      d.pointY = s.point_y;
      d.radius = s.radius;
      d.recTopX = s.rec_top_x;
      d.recTopY = s.rec_top_y;
      d.recBottomX = s.rec_bottom_x;
      d.recBottomY = s.rec_bottom_y;
      break;
    }
    case MAVLINK_MSG_ID_LANDING_TARGET: {
      mavlink_landing_target_t t;
      mavlink_msg_landing_target_decode(&m, &t);
      d.timeUsec = t.time_usec;
      d.angleX = t.angle_x;
      d.angleY = t.angle_y;
      d.distance = t.distance;
      d.sizeX = t.size_x;
      d.sizeY = t.size_y;
      d.x = t.x;
      d.y = t.y;
      d.z = t.z;
      d.frame = t.frame;
      d.type = t.type;
      d.positionValid = t.position_valid;
      break;
    }
    case MAVLINK_MSG_ID_COMMAND_ACK: {
      mavlink_command_ack_t a;
      mavlink_msg_command_ack_decode(&m, &a);
      d.ackCommand = a.command;
      d.ackResult = a.result;
      d.ackTargetSystem = a.target_system;
      d.ackTargetComponent = a.target_component;
      break;
    }
    case MAVLINK_MSG_ID_CAMERA_INFORMATION: {
      mavlink_camera_information_t c;
      mavlink_msg_camera_information_decode(&m, &c);
      d.camFlags = c.flags;
      d.camResolutionH = c.resolution_h;
      d.camResolutionV = c.resolution_v;
      std::memcpy(d.camVendor, c.vendor_name, 32);
      break;
    }
    default:
      break;
  }
  *out = d;
  return 1;
}

size_t encodeCommandLong(uint8_t sysId, uint8_t compId, uint8_t targetSys, uint8_t targetComp,
                         uint16_t command, const float params[7], uint8_t* out, size_t cap) {
  mavlink_message_t msg;
  mavlink_msg_command_long_pack(sysId, compId, &msg, targetSys, targetComp, command, 0, params[0],
                                params[1], params[2], params[3], params[4], params[5], params[6]);
  uint8_t buf[MAVLINK_MAX_PACKET_LEN];
  const uint16_t n = mavlink_msg_to_send_buffer(buf, &msg);
  if (n > cap) return 0;
  std::memcpy(out, buf, n);
  return n;
}

size_t encodeSignedCommandLong(uint8_t sysId, uint8_t compId, uint8_t targetSys, uint8_t targetComp,
                               uint16_t command, const float params[7], const uint8_t key[32],
                               uint8_t linkId, uint64_t timestamp, uint8_t* out, size_t cap) {
  mavlink_signing_t signing{};
  signing.flags = MAVLINK_SIGNING_FLAG_SIGN_OUTGOING;
  signing.link_id = linkId;
  signing.timestamp = timestamp;
  std::memcpy(signing.secret_key, key, 32);
  mavlink_status_t* status = mavlink_get_channel_status(MAVLINK_COMM_0);
  status->signing = &signing;  // the pack functions sign on channel 0's settings
  mavlink_message_t msg;
  mavlink_msg_command_long_pack(sysId, compId, &msg, targetSys, targetComp, command, 0, params[0],
                                params[1], params[2], params[3], params[4], params[5], params[6]);
  status->signing = nullptr;
  uint8_t buf[MAVLINK_MAX_PACKET_LEN];
  const uint16_t n = mavlink_msg_to_send_buffer(buf, &msg);
  if (n > cap) return 0;
  std::memcpy(out, buf, n);
  return n;
}

bool verifiesSigned(const uint8_t* frame, size_t n, const uint8_t key[32]) {
  mavlink_signing_t signing{};
  std::memcpy(signing.secret_key, key, 32);
  mavlink_signing_streams_t streams{};
  mavlink_status_t status{};
  status.signing = &signing;
  status.signing_streams = &streams;
  mavlink_message_t rx{}, msg{};
  mavlink_status_t msgStatus{};
  bool ok = false;
  for (size_t i = 0; i < n; ++i) {
    const uint8_t r = mavlink_frame_char_buffer(&rx, &status, frame[i], &msg, &msgStatus);
    if (r == MAVLINK_FRAMING_OK) ok = (msg.incompat_flags & MAVLINK_IFLAG_SIGNED) != 0;
    if (r == MAVLINK_FRAMING_BAD_CRC || r == MAVLINK_FRAMING_BAD_SIGNATURE) return false;
  }
  return ok;
}

uint8_t crcExtraOf(uint32_t msgId) {
  const mavlink_msg_entry_t* e = mavlink_get_msg_entry(msgId);
  return e ? e->crc_extra : 0;
}

}  // namespace cuetrack::test::official
