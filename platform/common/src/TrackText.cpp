#include "cuetrack/platform/TrackText.hpp"

#include <cinttypes>
#include <cmath>
#include <cstdio>

namespace cuetrack::platform {
namespace {

size_t finish(int n, size_t cap) {
  return (n < 0 || static_cast<size_t>(n) >= cap) ? 0 : static_cast<size_t>(n);
}

int16_t toPx(float v) {
  if (!(v == v)) return 0;  // NaN: the tracker never gives one, but the wire must stay valid
  const float r = std::round(v);
  if (r > 32767.f) return 32767;
  if (r < -32768.f) return -32768;
  return static_cast<int16_t>(r);
}

int32_t toMm(float v) {
  if (!(v == v)) return 0;
  const double r = std::round(static_cast<double>(v));
  if (r > 2147483647.0) return INT32_MAX;
  if (r < -2147483648.0) return INT32_MIN;
  return static_cast<int32_t>(r);
}

double confidenceOf(const ctp_track_t& t) {
  return t.confidence / 65535.0;
}

}  // namespace

ctp_track_t toTrackMessage(const TrackResult& r, uint64_t frameTimeUs, uint32_t procUs,
                           uint8_t previousState) {
  ctp_track_t t{};
  t.time_us = frameTimeUs;
  t.proc_us = procUs;
  switch (r.state) {
    case TrackState::Tracking:
      t.state = CTP_STATE_TRACKING;
      break;
    case TrackState::Lost:
      t.state = (previousState == CTP_STATE_LOST || previousState == CTP_STATE_SEARCHING)
                    ? CTP_STATE_SEARCHING
                    : CTP_STATE_LOST;
      break;
    default:
      t.state = CTP_STATE_IDLE;
      break;
  }
  if (t.state == CTP_STATE_IDLE) return t;  // no box, no centre
  t.box_px[0] = toPx(r.box.x);
  t.box_px[1] = toPx(r.box.y);
  t.box_px[2] = toPx(r.box.w);
  t.box_px[3] = toPx(r.box.h);
  if (r.hasPosition3d) {
    t.flags |= CTP_FLAG_HAS_3D;
    for (int i = 0; i < 3; ++i) t.centre_mm[i] = toMm(r.positionMm[i]);
  }
  if (r.learned) t.flags |= CTP_FLAG_LEARNED;
  if (r.occluded) t.flags |= CTP_FLAG_OCCLUDED;
  if (r.depthPredicted) t.flags |= CTP_FLAG_DEPTH_PREDICTED;
  float c = r.confidence;
  if (!(c >= 0.f)) c = 0.f;
  if (c > 1.f) c = 1.f;
  t.confidence = static_cast<uint16_t>(std::lround(static_cast<double>(c) * 65535.0));
  return t;
}

size_t formatTrackLine(const ctp_track_t& t, char* buf, size_t cap) {
  char mm[48] = "-";
  if (t.flags & CTP_FLAG_HAS_3D) {
    std::snprintf(mm, sizeof mm, "%" PRId32 ",%" PRId32 ",%" PRId32, t.centre_mm[0], t.centre_mm[1],
                  t.centre_mm[2]);
  }
  const int n = std::snprintf(
      buf, cap,
      "track seq=%" PRIu32 " t=%" PRIu64 "us %s box=%d,%d,%d,%d mm=%s conf=%.3f%s%s%s proc=%" PRIu32
      "us\n",
      t.seq, t.time_us, ctp_state_name(t.state), t.box_px[0], t.box_px[1], t.box_px[2], t.box_px[3],
      mm, confidenceOf(t), (t.flags & CTP_FLAG_LEARNED) ? " learned" : "",
      (t.flags & CTP_FLAG_OCCLUDED) ? " occluded" : "",
      (t.flags & CTP_FLAG_DEPTH_PREDICTED) ? " depth-predicted" : "", t.proc_us);
  return finish(n, cap);
}

const char* trackCsvHeader() {
  return "seq,time_us,state,x_px,y_px,w_px,h_px,has_3d,x_mm,y_mm,z_mm,confidence,learned,proc_us,"
         "occluded,depth_predicted\n";
}

size_t formatTrackCsvRow(const ctp_track_t& t, char* buf, size_t cap) {
  const int n = std::snprintf(
      buf, cap,
      "%" PRIu32 ",%" PRIu64 ",%s,%d,%d,%d,%d,%d,%" PRId32 ",%" PRId32 ",%" PRId32
      ",%.5f,%d,%" PRIu32 ",%d,%d\n",
      t.seq, t.time_us, ctp_state_name(t.state), t.box_px[0], t.box_px[1], t.box_px[2], t.box_px[3],
      (t.flags & CTP_FLAG_HAS_3D) ? 1 : 0, t.centre_mm[0], t.centre_mm[1], t.centre_mm[2],
      confidenceOf(t), (t.flags & CTP_FLAG_LEARNED) ? 1 : 0, t.proc_us,
      (t.flags & CTP_FLAG_OCCLUDED) ? 1 : 0, (t.flags & CTP_FLAG_DEPTH_PREDICTED) ? 1 : 0);
  return finish(n, cap);
}

size_t formatMessageLine(const ctp_message_t& m, char* buf, size_t cap) {
  int n = -1;
  switch (m.type) {
    case CTP_MSG_TRACK:
      return formatTrackLine(m.u.track, buf, cap);
    case CTP_MSG_HEARTBEAT:
      n = std::snprintf(buf, cap,
                        "heartbeat seq=%" PRIu32 " t=%" PRIu64 "us %s frames=%" PRIu32
                        " rx_errors=%" PRIu32 "%s\n",
                        m.u.heartbeat.seq, m.u.heartbeat.time_us,
                        ctp_state_name(m.u.heartbeat.state), m.u.heartbeat.frames,
                        m.u.heartbeat.rx_errors,
                        (m.u.heartbeat.flags & CTP_HB_NO_CAMERA) != 0 ? " no-camera" : "");
      break;
    case CTP_MSG_ACK:
      n = std::snprintf(buf, cap, "ack seq=%" PRIu32 " %s id=%u\n", m.u.ack.seq,
                        ctp_type_name(m.u.ack.cmd_type), static_cast<unsigned>(m.u.ack.cmd_id));
      break;
    case CTP_MSG_ERROR:
      n = std::snprintf(buf, cap, "error seq=%" PRIu32 " %s id=%u code=%s\n", m.u.error.seq,
                        ctp_type_name(m.u.error.cmd_type), static_cast<unsigned>(m.u.error.cmd_id),
                        ctp_error_name(m.u.error.code));
      break;
    default:
      n = std::snprintf(buf, cap, "unknown type=0x%02x\n", m.type);
      break;
  }
  return finish(n, cap);
}

}  // namespace cuetrack::platform
