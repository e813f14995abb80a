// The official MAVLink C library (../shared/tools/mavlink-c), behind a small interface,
// so that tests check cuetrack's MAVLink against an implementation nobody here wrote.
// Tests only: compiled from the shared folder when it is there (CUETRACK_HAVE_MAVLINK_C),
// never copied into the project, never linked into the product.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack::test::official {

// Every field tests look at, of the messages cuetrack sends, as the library decoded them.
struct Decoded {
  uint32_t msgId = 0;
  uint8_t seq = 0, sysId = 0, compId = 0;
  // HEARTBEAT
  uint8_t hbType = 0, hbAutopilot = 0, hbSystemStatus = 0;
  uint32_t hbCustomMode = 0;
  // CAMERA_TRACKING_IMAGE_STATUS
  uint8_t trackingStatus = 0, trackingMode = 0, targetData = 0;
  float pointX = 0, pointY = 0, radius = 0;
  float recTopX = 0, recTopY = 0, recBottomX = 0, recBottomY = 0;
  // LANDING_TARGET
  uint64_t timeUsec = 0;
  float angleX = 0, angleY = 0, distance = 0, sizeX = 0, sizeY = 0, x = 0, y = 0, z = 0;
  uint8_t frame = 0, type = 0, positionValid = 0;
  // COMMAND_ACK
  uint16_t ackCommand = 0;
  uint8_t ackResult = 0, ackTargetSystem = 0, ackTargetComponent = 0;
  // CAMERA_INFORMATION
  uint32_t camFlags = 0;
  uint16_t camResolutionH = 0, camResolutionV = 0;
  char camVendor[33] = {};
};

class Decoder {
 public:
  Decoder();
  ~Decoder();
  Decoder(const Decoder&) = delete;
  Decoder& operator=(const Decoder&) = delete;
  // 1: a message with a good CRC in *out; -1: a frame with a bad CRC; 0: need more bytes.
  int push(uint8_t byte, Decoded* out);

 private:
  struct State;
  State* _s;
};

// COMMAND_LONG from (sysId, compId) to (targetSys, targetComp), framed by the library.
size_t encodeCommandLong(uint8_t sysId, uint8_t compId, uint8_t targetSys, uint8_t targetComp,
                         uint16_t command, const float params[7], uint8_t* out, size_t cap);

// The same, signed by the library (MAVLink 2 signing with key, linkId, timestamp).
size_t encodeSignedCommandLong(uint8_t sysId, uint8_t compId, uint8_t targetSys, uint8_t targetComp,
                               uint16_t command, const float params[7], const uint8_t key[32],
                               uint8_t linkId, uint64_t timestamp, uint8_t* out, size_t cap);
// True when the library's parser, given key, takes the frame as correctly signed.
bool verifiesSigned(const uint8_t* frame, size_t n, const uint8_t key[32]);

// The library's own CRC_EXTRA for a message id (0 when it does not know it), and a full
// frame of id with our payload bytes, packed by the library's framing code.
uint8_t crcExtraOf(uint32_t msgId);

}  // namespace cuetrack::test::official
