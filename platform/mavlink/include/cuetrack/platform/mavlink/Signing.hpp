// MAVLink 2 message signing, as the spec defines it: a 13-byte block after the CRC of a
// frame whose incompat flag 0x01 is set: the link id, a 48-bit timestamp (10 us units since
// 2015-01-01 00:00 UTC, little-endian) and the first 48 bits of
// SHA-256(key, the 10 header bytes, the payload, the CRC, link id, timestamp). Replays are
// refused per stream (sender system, component and link id): each timestamp must be newer
// than that stream's last, and a new stream's at most a minute older than the newest
// timestamp known. No allocation, no OS.
#pragma once

#include <cstddef>
#include <cstdint>

#include "cuetrack/platform/mavlink/MavlinkCodec.hpp"

namespace cuetrack::platform::mavlink {

struct SigningKey {
  uint8_t bytes[32]{};
};

inline constexpr uint64_t kSigningEpochUnixS = 1420070400;   // 2015-01-01 00:00:00 UTC
inline constexpr uint64_t kSigningNewStreamSlack = 6000000;  // one minute in 10 us units

// The 6 signature bytes of a frame: header[10] (incompat flag set), payload[len], crc[2],
// and the block's link id and timestamp (block[0..6]); written to block[7..12].
void signBlock(const SigningKey& key, const uint8_t* header, const uint8_t* payload, size_t len,
               const uint8_t crc[2], uint8_t block[kSignatureBytes]);

// One signed MAVLink 2 frame into out (payload truncated as encodeFrame does). Returns its
// size, or 0 when msgId is unknown, len exceeds the message's payload, or cap is too small.
size_t encodeSignedFrame(const Header& h, const uint8_t* payload, size_t len, const SigningKey& key,
                         uint8_t linkId, uint64_t timestamp, uint8_t* out, size_t cap);

enum class SignatureCheck : uint8_t {
  Good,
  Unsigned,
  BadSignature,
  Replayed,
  TooOld,
  TooManyStreams
};

class SignatureChecker {
 public:
  static constexpr int kMaxStreams = 16;
  explicit SignatureChecker(const SigningKey& key) : _key(key) {}
  // A parsed message: Good only when signed with our key and newer than its stream's last.
  SignatureCheck check(const Message& m);
  // Our own clock's timestamp (what we sign with): a new stream must not be older.
  void noteTimestamp(uint64_t t) {
    if (t > _newest) _newest = t;
  }
  uint64_t newest() const { return _newest; }

 private:
  struct Stream {
    uint8_t sysId, compId, linkId;
    uint64_t last;
  };
  SigningKey _key;
  Stream _streams[kMaxStreams]{};
  int _count{0};
  uint64_t _newest{0};
};

}  // namespace cuetrack::platform::mavlink
