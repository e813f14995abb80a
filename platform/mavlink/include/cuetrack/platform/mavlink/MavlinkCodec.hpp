// MAVLink 2 framing, our own: the encoder, a byte-at-a-time parser, CRC-16/MCRF4XX with
// each message's CRC_EXTRA. No allocation, no OS. Message ids, payload layouts and
// CRC_EXTRA values are those of the official generated headers (common.xml, minimal.xml);
// docs/mavlink.md has the frame byte for byte.
//
// Frame: 0xFD len incompat compat seq sysid compid msgid[3] payload[len] crc[2] [sig 13]
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack::platform::mavlink {

inline constexpr uint8_t kStx = 0xFD;       // MAVLink 2 start byte
inline constexpr size_t kHeaderBytes = 10;  // STX .. msgid
inline constexpr size_t kCrcBytes = 2;
inline constexpr size_t kSignatureBytes = 13;
inline constexpr size_t kMaxPayloadBytes = 255;
inline constexpr size_t kMaxFrameBytes =
    kHeaderBytes + kMaxPayloadBytes + kCrcBytes + kSignatureBytes;
inline constexpr uint8_t kIncompatSigned = 0x01;  // the only incompat flag defined

// The messages we send or read.
enum MessageId : uint32_t {
  kMsgHeartbeat = 0,
  kMsgCommandInt = 75,
  kMsgCommandLong = 76,
  kMsgCommandAck = 77,
  kMsgLandingTarget = 149,
  kMsgCameraInformation = 259,
  kMsgCameraTrackingImageStatus = 275,
};

struct MessageInfo {
  uint32_t id;
  uint8_t crcExtra;
  uint8_t payloadBytes;  // with every extension field
};
// nullptr for a message we do not know (its CRC cannot be checked).
const MessageInfo* messageInfo(uint32_t id);

// CRC-16/MCRF4XX (X.25 as MAVLink computes it): poly 0x1021 reflected, init 0xFFFF.
uint16_t crcAccumulate(uint8_t byte, uint16_t crc);
uint16_t crc16(const uint8_t* data, size_t n, uint16_t crc = 0xFFFF);

struct Header {
  uint8_t seq = 0;
  uint8_t sysId = 0;
  uint8_t compId = 0;
  uint32_t msgId = 0;
};

// One unsigned MAVLink 2 frame into out. The payload's trailing zero bytes are cut (as
// MAVLink 2 requires senders to; at least one byte stays). Returns the frame's size, or 0
// when msgId is unknown, len exceeds the message's payload, or cap is too small.
// incompatFlags: kIncompatSigned for a frame a signature block will follow (Signing.hpp).
size_t encodeFrame(const Header& h, const uint8_t* payload, size_t len, uint8_t* out, size_t cap,
                   uint8_t incompatFlags = 0);

struct Message {
  Header header{};
  uint8_t incompatFlags = 0;
  uint8_t compatFlags = 0;
  uint8_t len = 0;                       // as sent (maybe truncated)
  uint8_t payload[kMaxPayloadBytes]{};   // zero past len: truncated fields read as 0
  uint16_t crc = 0;                      // as sent
  uint8_t signature[kSignatureBytes]{};  // signed frames: link id, timestamp, signature
};

struct ParserStats {
  uint32_t messages = 0;  // known id, good CRC
  uint32_t badCrc = 0;    // known id, CRC wrong
  uint32_t badFrame = 0;  // unknown incompat flag, longer than its message, or (datagrams)
                          // cut by the datagram's end
  uint32_t ignored = 0;   // well-framed, an id we do not know (another component's traffic)
};

// Byte-at-a-time parser. Bytes before a start byte (noise, MAVLink 1 frames) are
// skipped; after a bad frame it looks for the next start byte inside that frame's bytes,
// so a false start in noise does not swallow the good frame that follows.
class Parser {
 public:
  // True when `byte` completed a good message (copied to *out).
  bool push(uint8_t byte, Message* out);
  // A whole datagram (MAVLink over UDP: whole frames, one or more to a datagram), parsed on
  // its own: nothing is kept for the next one, and a frame its end cuts is a bad frame.
  // Finds the next good message from *offset on (moved past it); false at the end. The
  // byte stream's held bytes (push) are neither used nor changed; the stats are shared.
  bool nextInDatagram(const uint8_t* data, size_t n, size_t* offset, Message* out);
  const ParserStats& stats() const { return _stats; }
  void reset() { _n = 0; }

 private:
  void resync();  // drop the first byte, restart at the next start byte

  uint8_t _buf[kMaxFrameBytes]{};
  size_t _n{0};
  ParserStats _stats{};
};

}  // namespace cuetrack::platform::mavlink
