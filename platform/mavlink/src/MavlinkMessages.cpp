#include "cuetrack/platform/mavlink/MavlinkMessages.hpp"

#include <cstring>

namespace cuetrack::platform::mavlink {
namespace {

// Explicit little-endian bytes: the wire order does not depend on the host's.
void put8(uint8_t* p, size_t at, uint8_t v) {
  p[at] = v;
}
void put16(uint8_t* p, size_t at, uint16_t v) {
  p[at] = static_cast<uint8_t>(v);
  p[at + 1] = static_cast<uint8_t>(v >> 8);
}
void put32(uint8_t* p, size_t at, uint32_t v) {
  for (int i = 0; i < 4; ++i) p[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
void put64(uint8_t* p, size_t at, uint64_t v) {
  for (int i = 0; i < 8; ++i) p[at + i] = static_cast<uint8_t>(v >> (8 * i));
}
void putF(uint8_t* p, size_t at, float v) {
  uint32_t bits;
  std::memcpy(&bits, &v, 4);
  put32(p, at, bits);
}
void putChars(uint8_t* p, size_t at, const char* s, size_t n) {
  for (size_t i = 0; i < n; ++i) p[at + i] = static_cast<uint8_t>(s[i]);
}
uint16_t get16(const uint8_t* p, size_t at) {
  return static_cast<uint16_t>(p[at] | (p[at + 1] << 8));
}
uint32_t get32(const uint8_t* p, size_t at) {
  uint32_t v = 0;
  for (int i = 3; i >= 0; --i) v = (v << 8) | p[at + i];
  return v;
}
uint64_t get64(const uint8_t* p, size_t at) {
  uint64_t v = 0;
  for (int i = 7; i >= 0; --i) v = (v << 8) | p[at + i];
  return v;
}
float getF(const uint8_t* p, size_t at) {
  const uint32_t bits = get32(p, at);
  float v;
  std::memcpy(&v, &bits, 4);
  return v;
}

}  // namespace

size_t pack(const Heartbeat& m, uint8_t* out) {
  put32(out, 0, m.customMode);
  put8(out, 4, m.type);
  put8(out, 5, m.autopilot);
  put8(out, 6, m.baseMode);
  put8(out, 7, m.systemStatus);
  put8(out, 8, m.mavlinkVersion);
  return 9;
}

size_t pack(const CommandLong& m, uint8_t* out) {
  for (int i = 0; i < 7; ++i) putF(out, 4 * static_cast<size_t>(i), m.param[i]);
  put16(out, 28, m.command);
  put8(out, 30, m.targetSystem);
  put8(out, 31, m.targetComponent);
  put8(out, 32, m.confirmation);
  return 33;
}

size_t pack(const CommandAck& m, uint8_t* out) {
  put16(out, 0, m.command);
  put8(out, 2, m.result);
  put8(out, 3, m.progress);
  put32(out, 4, static_cast<uint32_t>(m.resultParam2));
  put8(out, 8, m.targetSystem);
  put8(out, 9, m.targetComponent);
  return 10;
}

size_t pack(const CameraTrackingImageStatus& m, uint8_t* out) {
  putF(out, 0, m.pointX);
  putF(out, 4, m.pointY);
  putF(out, 8, m.radius);
  putF(out, 12, m.recTopX);
  putF(out, 16, m.recTopY);
  putF(out, 20, m.recBottomX);
  putF(out, 24, m.recBottomY);
  put8(out, 28, m.trackingStatus);
  put8(out, 29, m.trackingMode);
  put8(out, 30, m.targetData);
  put8(out, 31, m.cameraDeviceId);
  return 32;
}

size_t pack(const LandingTarget& m, uint8_t* out) {
  put64(out, 0, m.timeUsec);
  putF(out, 8, m.angleX);
  putF(out, 12, m.angleY);
  putF(out, 16, m.distance);
  putF(out, 20, m.sizeX);
  putF(out, 24, m.sizeY);
  put8(out, 28, m.targetNum);
  put8(out, 29, m.frame);
  putF(out, 30, m.x);
  putF(out, 34, m.y);
  putF(out, 38, m.z);
  for (int i = 0; i < 4; ++i) putF(out, 42 + 4 * static_cast<size_t>(i), m.q[i]);
  put8(out, 58, m.type);
  put8(out, 59, m.positionValid);
  return 60;
}

size_t pack(const CameraInformation& m, uint8_t* out) {
  put32(out, 0, m.timeBootMs);
  put32(out, 4, m.firmwareVersion);
  putF(out, 8, m.focalLength);
  putF(out, 12, m.sensorSizeH);
  putF(out, 16, m.sensorSizeV);
  put32(out, 20, m.flags);
  put16(out, 24, m.resolutionH);
  put16(out, 26, m.resolutionV);
  put16(out, 28, m.camDefinitionVersion);
  putChars(out, 30, m.vendorName, 32);
  putChars(out, 62, m.modelName, 32);
  put8(out, 94, m.lensId);
  putChars(out, 95, m.camDefinitionUri, 140);
  put8(out, 235, m.gimbalDeviceId);
  put8(out, 236, m.cameraDeviceId);
  return 237;
}

Heartbeat unpackHeartbeat(const uint8_t* p) {
  Heartbeat m;
  m.customMode = get32(p, 0);
  m.type = p[4];
  m.autopilot = p[5];
  m.baseMode = p[6];
  m.systemStatus = p[7];
  m.mavlinkVersion = p[8];
  return m;
}

CommandLong unpackCommandLong(const uint8_t* p) {
  CommandLong m;
  for (int i = 0; i < 7; ++i) m.param[i] = getF(p, 4 * static_cast<size_t>(i));
  m.command = get16(p, 28);
  m.targetSystem = p[30];
  m.targetComponent = p[31];
  m.confirmation = p[32];
  return m;
}

CommandInt unpackCommandInt(const uint8_t* p) {
  CommandInt m;
  m.command = get16(p, 28);
  m.targetSystem = p[30];
  m.targetComponent = p[31];
  return m;
}

CommandAck unpackCommandAck(const uint8_t* p) {
  CommandAck m;
  m.command = get16(p, 0);
  m.result = p[2];
  m.progress = p[3];
  m.resultParam2 = static_cast<int32_t>(get32(p, 4));
  m.targetSystem = p[8];
  m.targetComponent = p[9];
  return m;
}

CameraTrackingImageStatus unpackCameraTrackingImageStatus(const uint8_t* p) {
  CameraTrackingImageStatus m;
  m.pointX = getF(p, 0);
  m.pointY = getF(p, 4);
  m.radius = getF(p, 8);
  m.recTopX = getF(p, 12);
  m.recTopY = getF(p, 16);
  m.recBottomX = getF(p, 20);
  m.recBottomY = getF(p, 24);
  m.trackingStatus = p[28];
  m.trackingMode = p[29];
  m.targetData = p[30];
  m.cameraDeviceId = p[31];
  return m;
}

LandingTarget unpackLandingTarget(const uint8_t* p) {
  LandingTarget m;
  m.timeUsec = get64(p, 0);
  m.angleX = getF(p, 8);
  m.angleY = getF(p, 12);
  m.distance = getF(p, 16);
  m.sizeX = getF(p, 20);
  m.sizeY = getF(p, 24);
  m.targetNum = p[28];
  m.frame = p[29];
  m.x = getF(p, 30);
  m.y = getF(p, 34);
  m.z = getF(p, 38);
  for (int i = 0; i < 4; ++i) m.q[i] = getF(p, 42 + 4 * static_cast<size_t>(i));
  m.type = p[58];
  m.positionValid = p[59];
  return m;
}

}  // namespace cuetrack::platform::mavlink
