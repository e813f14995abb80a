#include "cuetrack/platform/mavlink/Signing.hpp"

#include <cstring>

#include "cuetrack/platform/mavlink/Sha256.hpp"

namespace cuetrack::platform::mavlink {

void signBlock(const SigningKey& key, const uint8_t* header, const uint8_t* payload, size_t len,
               const uint8_t crc[2], uint8_t block[kSignatureBytes]) {
  Sha256 sha;
  sha.update(key.bytes, sizeof key.bytes);
  sha.update(header, kHeaderBytes);
  sha.update(payload, len);
  sha.update(crc, kCrcBytes);
  sha.update(block, 7);
  uint8_t digest[32];
  sha.final(digest);
  std::memcpy(block + 7, digest, 6);
}

size_t encodeSignedFrame(const Header& h, const uint8_t* payload, size_t len, const SigningKey& key,
                         uint8_t linkId, uint64_t timestamp, uint8_t* out, size_t cap) {
  const size_t n = encodeFrame(h, payload, len, out, cap, kIncompatSigned);
  if (n == 0 || cap < n + kSignatureBytes) return 0;
  const size_t payloadLen = out[1];
  uint8_t* block = out + n;
  block[0] = linkId;
  for (int i = 0; i < 6; ++i) block[1 + i] = static_cast<uint8_t>(timestamp >> (8 * i));
  signBlock(key, out, out + kHeaderBytes, payloadLen, out + kHeaderBytes + payloadLen, block);
  return n + kSignatureBytes;
}

SignatureCheck SignatureChecker::check(const Message& m, uint64_t clockNow) {
  if ((m.incompatFlags & kIncompatSigned) == 0) return SignatureCheck::Unsigned;
  const uint8_t header[kHeaderBytes] = {kStx,
                                        m.len,
                                        m.incompatFlags,
                                        m.compatFlags,
                                        m.header.seq,
                                        m.header.sysId,
                                        m.header.compId,
                                        static_cast<uint8_t>(m.header.msgId & 0xFF),
                                        static_cast<uint8_t>((m.header.msgId >> 8) & 0xFF),
                                        static_cast<uint8_t>((m.header.msgId >> 16) & 0xFF)};
  const uint8_t crc[kCrcBytes] = {static_cast<uint8_t>(m.crc & 0xFF),
                                  static_cast<uint8_t>(m.crc >> 8)};
  uint8_t block[kSignatureBytes];
  std::memcpy(block, m.signature, 7);
  signBlock(_key, header, m.payload, m.len, crc, block);
  // Every byte compared, whatever differs first.
  uint8_t diff = 0;
  for (int i = 7; i < 13; ++i) diff |= static_cast<uint8_t>(block[i] ^ m.signature[i]);
  if (diff != 0) return SignatureCheck::BadSignature;
  uint64_t t = 0;
  for (int i = 0; i < 6; ++i) t |= static_cast<uint64_t>(m.signature[1 + i]) << (8 * i);
  const uint64_t latest = clockNow == 0 ? kSigningLatestBelievable : clockNow + kSigningAheadSlack;
  if (t > latest || t > kSigningLatestBelievable) return SignatureCheck::TooNew;
  const uint8_t linkId = m.signature[0];
  Stream* s = nullptr;
  for (int i = 0; i < _count; ++i)
    if (_streams[i].sysId == m.header.sysId && _streams[i].compId == m.header.compId &&
        _streams[i].linkId == linkId)
      s = &_streams[i];
  if (s == nullptr) {
    if (_count == kMaxStreams) return SignatureCheck::TooManyStreams;
    if (t + kSigningNewStreamSlack < _newest) return SignatureCheck::TooOld;
    s = &_streams[_count++];
    *s = Stream{m.header.sysId, m.header.compId, linkId, t};
  } else if (t <= s->last) {
    return SignatureCheck::Replayed;
  }
  s->last = t;
  noteTimestamp(t);
  return SignatureCheck::Good;
}

}  // namespace cuetrack::platform::mavlink
