// The payloads of the MAVLink messages cuetrack sends and reads, packed and unpacked
// field by field in little-endian byte order (the same bytes on x86, aarch64 and armhf).
// Offsets follow the official generated headers (fields sorted by size, extensions last).
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/platform/mavlink/MavlinkCodec.hpp"

namespace cuetrack::platform::mavlink {

// Enum values from common.xml / minimal.xml.
inline constexpr uint8_t kMavTypeCamera = 30;
inline constexpr uint8_t kMavAutopilotInvalid = 8;
inline constexpr uint8_t kMavStateBoot = 1;
inline constexpr uint8_t kMavStateStandby = 3;
inline constexpr uint8_t kMavStateActive = 4;
inline constexpr uint8_t kMavlinkVersion = 3;
inline constexpr uint8_t kMavCompIdCamera = 100;
inline constexpr uint8_t kMavFrameBodyFrd = 12;
inline constexpr uint8_t kLandingTargetTypeVisionOther = 3;

enum MavCmd : uint16_t {
  kCmdSetMessageInterval = 511,
  kCmdRequestMessage = 512,
  kCmdCameraTrackPoint = 2004,
  kCmdCameraTrackRectangle = 2005,
  kCmdCameraStopTracking = 2010,
};

enum MavResult : uint8_t {
  kResultAccepted = 0,
  kResultTemporarilyRejected = 1,
  kResultDenied = 2,
  kResultUnsupported = 3,
  kResultFailed = 4,
  kResultCancelled = 6,
  kResultCommandLongOnly = 7,
};

inline constexpr uint32_t kCameraCapHasTrackingPoint = 512;
inline constexpr uint32_t kCameraCapHasTrackingRectangle = 1024;
inline constexpr uint8_t kTrackingStatusIdle = 0;
inline constexpr uint8_t kTrackingStatusActive = 1;
inline constexpr uint8_t kTrackingStatusError = 2;
inline constexpr uint8_t kTrackingModeNone = 0;
inline constexpr uint8_t kTrackingModePoint = 1;
inline constexpr uint8_t kTrackingModeRectangle = 2;
inline constexpr uint8_t kTrackingTargetDataInStatus = 4;

struct Heartbeat {  // HEARTBEAT (0), 9 bytes
  uint32_t customMode = 0;
  uint8_t type = 0, autopilot = 0, baseMode = 0, systemStatus = 0, mavlinkVersion = kMavlinkVersion;
};

struct CommandLong {  // COMMAND_LONG (76), 33 bytes
  float param[7] = {0, 0, 0, 0, 0, 0, 0};
  uint16_t command = 0;
  uint8_t targetSystem = 0, targetComponent = 0, confirmation = 0;
};

struct CommandInt {  // COMMAND_INT (75): only what it takes to refuse it properly
  uint16_t command = 0;
  uint8_t targetSystem = 0, targetComponent = 0;
};

struct CommandAck {  // COMMAND_ACK (77), 10 bytes
  uint16_t command = 0;
  uint8_t result = 0, progress = 0;
  int32_t resultParam2 = 0;
  uint8_t targetSystem = 0, targetComponent = 0;
};

struct CameraTrackingImageStatus {  // CAMERA_TRACKING_IMAGE_STATUS (275), 32 bytes
  float pointX = 0, pointY = 0, radius = 0;
  float recTopX = 0, recTopY = 0, recBottomX = 0, recBottomY = 0;
  uint8_t trackingStatus = 0, trackingMode = 0, targetData = 0, cameraDeviceId = 0;
};

struct LandingTarget {  // LANDING_TARGET (149), 60 bytes
  uint64_t timeUsec = 0;
  float angleX = 0, angleY = 0, distance = 0, sizeX = 0, sizeY = 0;
  uint8_t targetNum = 0, frame = 0;
  float x = 0, y = 0, z = 0;
  float q[4] = {1, 0, 0, 0};
  uint8_t type = 0, positionValid = 0;
};

struct CameraInformation {  // CAMERA_INFORMATION (259), 237 bytes
  uint32_t timeBootMs = 0, firmwareVersion = 0;
  float focalLength = 0, sensorSizeH = 0, sensorSizeV = 0;
  uint32_t flags = 0;
  uint16_t resolutionH = 0, resolutionV = 0, camDefinitionVersion = 0;
  char vendorName[32] = {};
  char modelName[32] = {};
  uint8_t lensId = 0;
  char camDefinitionUri[140] = {};
  uint8_t gimbalDeviceId = 0, cameraDeviceId = 0;
};

// pack: writes the full payload into out (cap >= the message's size), returns its size.
size_t pack(const Heartbeat& m, uint8_t* out);
size_t pack(const CommandLong& m, uint8_t* out);
size_t pack(const CommandAck& m, uint8_t* out);
size_t pack(const CameraTrackingImageStatus& m, uint8_t* out);
size_t pack(const LandingTarget& m, uint8_t* out);
size_t pack(const CameraInformation& m, uint8_t* out);
// unpack: from a parsed message's payload (zero-extended past its length).
Heartbeat unpackHeartbeat(const uint8_t* p);
CommandLong unpackCommandLong(const uint8_t* p);
CommandInt unpackCommandInt(const uint8_t* p);
CommandAck unpackCommandAck(const uint8_t* p);
CameraTrackingImageStatus unpackCameraTrackingImageStatus(const uint8_t* p);
LandingTarget unpackLandingTarget(const uint8_t* p);

}  // namespace cuetrack::platform::mavlink
