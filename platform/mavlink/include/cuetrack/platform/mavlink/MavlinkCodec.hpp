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

// Why bytes were thrown away (docs/mavlink.md, "Bad bytes").
enum class Discard : uint8_t {
  Crc,      // a message we know, its CRC wrong
  Length,   // a message we know longer than its definition, or a frame cut short (by a
            // datagram's end, or a checked frame starting inside it before its end came)
  Unknown,  // no frame: noise, MAVLink 1, an unknown incompat flag, or a header of a message
            // we do not know that a checked frame inside its claimed length contradicts
};
inline constexpr int kDiscardReasons = 3;

struct ParserStats {
  uint32_t messages = 0;  // known id, good CRC
  uint32_t ignored = 0;   // well-framed, an id we do not know (another component's traffic)
  uint64_t messageBytes = 0, ignoredBytes = 0;
  // Discarded runs by reason (consecutive Unknown runs count once), and their bytes: every
  // byte read is in a message, an ignored frame, or here.
  uint32_t errors[kDiscardReasons]{};
  uint64_t discardedBytes[kDiscardReasons]{};
  uint32_t badCrc() const { return errors[static_cast<int>(Discard::Crc)]; }
  uint32_t badLength() const { return errors[static_cast<int>(Discard::Length)]; }
  uint32_t badUnknown() const { return errors[static_cast<int>(Discard::Unknown)]; }
  uint32_t totalErrors() const { return badCrc() + badLength() + badUnknown(); }
};

// The parser of both transports, one resynchronisation for both. A header is never
// trusted for its length alone: before the bytes a header claims are skipped (a message
// we do not know, whose CRC cannot be checked) or waited for (any message not yet whole),
// the start bytes inside them are tried, and a frame there whose CRC checks is decoded;
// the false header's bytes are discarded and counted. A whole frame of an unknown id with
// no checked frame inside passes as another component's message. After a bad frame the
// next start byte inside it is tried.
class Parser {
 public:
  // Window large enough for any undecided state: a header's frame (at most kMaxFrameBytes)
  // and a frame starting inside it.
  static constexpr size_t kWindowBytes = 2 * kMaxFrameBytes;

  // A byte stream (serial): true when a message is ready in *out; then call next() until
  // false for any further message the same byte completed.
  bool push(uint8_t byte, Message* out);
  bool next(Message* out);
  // A whole datagram (MAVLink over UDP: whole frames, one or more to a datagram), parsed on
  // its own: nothing is kept for the next one, and a frame its end cuts is discarded.
  // Finds the next good message from *offset on (moved past it); false at the end. The
  // byte stream's held bytes (push) are neither used nor changed; the stats are shared.
  bool nextInDatagram(const uint8_t* data, size_t n, size_t* offset, Message* out);
  const ParserStats& stats() const { return _stats; }
  size_t held() const { return _n; }  // stream bytes not yet decided
  void reset();                       // forget held bytes (the line was reopened)

 private:
  enum class Kind : uint8_t { NeedMore, Good, Foreign, Discarded };
  struct Step {
    Kind kind;
    size_t bytes;  // consumed from the window's start
  };
  // What starts at w[0] of a window of n bytes whose first byte is stream position `pos`
  // (for the cache); final: no byte will follow (a datagram's end).
  Step step(const uint8_t* w, size_t n, uint64_t pos, bool final);
  // Whether a whole frame of a known id with a good CRC starts at w[0] (cached by position).
  bool verified(const uint8_t* w, size_t n, uint64_t pos);
  // The first p in [from, to) where a checked frame starts inside w[0..n), else 0.
  size_t verifiedIn(const uint8_t* w, size_t n, uint64_t pos, size_t from, size_t to);
  void discard(size_t bytes, Discard why);

  uint8_t _buf[kWindowBytes]{};
  size_t _n{0};
  uint64_t _streamPos{0};                    // of _buf[0]
  uint64_t _datagramPos{uint64_t{1} << 62};  // each datagram's own range of positions
  uint64_t _datagramBase{0};
  bool _inUnknownRun{false};
  // CRC results by stream position, so a byte is never checked as a frame start twice:
  // a crafted stream costs O(bytes x frame) rather than O(bytes x window x frame).
  static constexpr size_t kCacheSlots = 1024;
  uint64_t _cachePos[kCacheSlots]{};  // position + 1; 0: empty
  bool _cacheGood[kCacheSlots]{};
  ParserStats _stats{};
};

}  // namespace cuetrack::platform::mavlink
