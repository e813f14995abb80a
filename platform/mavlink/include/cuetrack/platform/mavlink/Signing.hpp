// MAVLink 2 message signing, as the spec defines it: a 13-byte block after the CRC of a
// frame whose incompat flag 0x01 is set: the link id, a 48-bit timestamp (10 us units since
// 2015-01-01 00:00 UTC, little-endian) and the first 48 bits of
// SHA-256(key, the 10 header bytes, the payload, the CRC, link id, timestamp). Replays are
// refused per stream (sender system, component and link id): each timestamp must be newer
// than that stream's last, and a new stream's at most a minute older than the newest
// timestamp known. A timestamp more than a minute ahead of our clock is refused. At most
// kMaxStreams streams are remembered (docs/mavlink.md). No allocation, no OS.
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
// A timestamp is 48 bits: the largest, in 2104. Ours never pass it (they would wrap to 0,
// and every receiver would then drop our traffic as replayed).
inline constexpr uint64_t kSigningMaxTimestamp = (uint64_t{1} << 48) - 1;
// An incoming timestamp this far ahead of our clock is refused, not adopted: one frame from
// the future (a peer's clock gone wrong, or a key holder's mischief) must not drag ours on.
inline constexpr uint64_t kSigningAheadSlack = 6000000;  // one minute in 10 us units
// While our clock is not known (a board without a real-time clock, before NTP): nothing
// after 2100-01-01 is believed. (4102444800 - 1420070400) s in 10 us units.
inline constexpr uint64_t kSigningLatestBelievable = 268237440000000ull;

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
  TooNew,  // more than kSigningAheadSlack ahead of our clock, or not believable
  TooManyStreams
};

class SignatureChecker {
 public:
  static constexpr int kMaxStreams = 16;
  explicit SignatureChecker(const SigningKey& key) : _key(key) {}
  // A parsed message: Good only when signed with our key, newer than its stream's last, and
  // at most kSigningAheadSlack ahead of clockNow (our clock in signing units; 0: not known,
  // then at most kSigningLatestBelievable).
  SignatureCheck check(const Message& m, uint64_t clockNow);
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
