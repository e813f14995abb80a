#include "cuetrack/platform/mavlink/MavlinkCodec.hpp"

#include <cstring>

namespace cuetrack::platform::mavlink {
namespace {

// From the official generated headers: MAVLINK_MSG_ID_<NAME>_CRC and _LEN.
constexpr MessageInfo kMessages[] = {
    {kMsgHeartbeat, 50, 9},
    {kMsgCommandInt, 158, 35},
    {kMsgCommandLong, 152, 33},
    {kMsgCommandAck, 143, 10},
    {kMsgLandingTarget, 200, 60},
    {kMsgCameraInformation, 92, 237},
    {kMsgCameraTrackingImageStatus, 126, 32},
};

uint32_t msgIdOf(const uint8_t* frame) {
  return static_cast<uint32_t>(frame[7]) | static_cast<uint32_t>(frame[8]) << 8 |
         static_cast<uint32_t>(frame[9]) << 16;
}

}  // namespace

const MessageInfo* messageInfo(uint32_t id) {
  for (const MessageInfo& m : kMessages)
    if (m.id == id) return &m;
  return nullptr;
}

uint16_t crcAccumulate(uint8_t byte, uint16_t crc) {
  uint8_t tmp = static_cast<uint8_t>(byte ^ static_cast<uint8_t>(crc & 0xFF));
  tmp = static_cast<uint8_t>(tmp ^ static_cast<uint8_t>(tmp << 4));
  return static_cast<uint16_t>((crc >> 8) ^ (static_cast<uint16_t>(tmp) << 8) ^
                               (static_cast<uint16_t>(tmp) << 3) ^ (tmp >> 4));
}

uint16_t crc16(const uint8_t* data, size_t n, uint16_t crc) {
  for (size_t i = 0; i < n; ++i) crc = crcAccumulate(data[i], crc);
  return crc;
}

size_t encodeFrame(const Header& h, const uint8_t* payload, size_t len, uint8_t* out, size_t cap,
                   uint8_t incompatFlags) {
  const MessageInfo* info = messageInfo(h.msgId);
  if (info == nullptr || len > info->payloadBytes) return 0;
  while (len > 1 && payload[len - 1] == 0) --len;  // MAVLink 2 payload truncation
  if (len == 0) len = 1;                           // an all-zero payload keeps one byte
  const size_t total = kHeaderBytes + len + kCrcBytes;
  if (cap < total) return 0;
  out[0] = kStx;
  out[1] = static_cast<uint8_t>(len);
  out[2] = incompatFlags;
  out[3] = 0;  // compat flags
  out[4] = h.seq;
  out[5] = h.sysId;
  out[6] = h.compId;
  out[7] = static_cast<uint8_t>(h.msgId & 0xFF);
  out[8] = static_cast<uint8_t>((h.msgId >> 8) & 0xFF);
  out[9] = static_cast<uint8_t>((h.msgId >> 16) & 0xFF);
  if (payload != nullptr)
    std::memcpy(out + kHeaderBytes, payload, len);
  else
    out[kHeaderBytes] = 0;
  uint16_t crc = crc16(out + 1, kHeaderBytes - 1 + len);
  crc = crcAccumulate(info->crcExtra, crc);
  out[kHeaderBytes + len] = static_cast<uint8_t>(crc & 0xFF);
  out[kHeaderBytes + len + 1] = static_cast<uint8_t>(crc >> 8);
  return total;
}

namespace {

// A header at w[0] (a start byte), judged on the n bytes there.
enum class Head : uint8_t { NeedMore, BadFlags, TooLong, Known, Unknown };
Head headOf(const uint8_t* w, size_t n, size_t* total, const MessageInfo** info) {
  if (n >= 3 && (w[2] & ~kIncompatSigned) != 0) return Head::BadFlags;
  if (n < kHeaderBytes) return Head::NeedMore;
  const size_t len = w[1];
  *info = messageInfo(msgIdOf(w));
  if (*info != nullptr && len > (*info)->payloadBytes) return Head::TooLong;
  *total = kHeaderBytes + len + kCrcBytes + ((w[2] & kIncompatSigned) ? kSignatureBytes : 0);
  return *info != nullptr ? Head::Known : Head::Unknown;
}

bool crcGood(const uint8_t* w, const MessageInfo& info) {
  const size_t len = w[1];
  uint16_t crc = crc16(w + 1, kHeaderBytes - 1 + len);
  crc = crcAccumulate(info.crcExtra, crc);
  return crc == static_cast<uint16_t>(w[kHeaderBytes + len] | (w[kHeaderBytes + len + 1] << 8));
}

// The next start byte after w[0], or n.
size_t nextStart(const uint8_t* w, size_t n) {
  size_t k = 1;
  while (k < n && w[k] != kStx) ++k;
  return k;
}

void copyMessage(const uint8_t* buf, Message* out) {
  out->header.seq = buf[4];
  out->header.sysId = buf[5];
  out->header.compId = buf[6];
  out->header.msgId = msgIdOf(buf);
  out->incompatFlags = buf[2];
  out->compatFlags = buf[3];
  out->len = buf[1];
  std::memset(out->payload, 0, sizeof out->payload);
  std::memcpy(out->payload, buf + kHeaderBytes, out->len);
  out->crc =
      static_cast<uint16_t>(buf[kHeaderBytes + out->len] | (buf[kHeaderBytes + out->len + 1] << 8));
  std::memset(out->signature, 0, sizeof out->signature);
  if ((buf[2] & kIncompatSigned) != 0)
    std::memcpy(out->signature, buf + kHeaderBytes + out->len + kCrcBytes, kSignatureBytes);
}

}  // namespace

bool Parser::verified(const uint8_t* w, size_t n, uint64_t pos) {
  size_t total = 0;
  const MessageInfo* info = nullptr;
  if (w[0] != kStx || headOf(w, n, &total, &info) != Head::Known || n < total) return false;
  const size_t slot = pos % kCacheSlots;
  if (_cachePos[slot] != pos + 1) {
    _cachePos[slot] = pos + 1;
    _cacheGood[slot] = crcGood(w, *info);
  }
  return _cacheGood[slot];
}

size_t Parser::verifiedIn(const uint8_t* w, size_t n, uint64_t pos, size_t from, size_t to) {
  if (to > n) to = n;
  for (size_t p = from; p < to; ++p)
    if (w[p] == kStx && verified(w + p, n - p, pos + p)) return p;
  return 0;
}

void Parser::discard(size_t bytes, Discard why) {
  const int r = static_cast<int>(why);
  _stats.discardedBytes[r] += bytes;
  if (why != Discard::Unknown || !_inUnknownRun) ++_stats.errors[r];  // one run, one error
  _inUnknownRun = why == Discard::Unknown;
}

Parser::Step Parser::step(const uint8_t* w, size_t n, uint64_t pos, bool final) {
  const auto thrown = [&](Discard why) {
    const size_t k = nextStart(w, n);  // the next start byte inside is tried next
    discard(k, why);
    return Step{Kind::Discarded, k};
  };
  if (w[0] != kStx) return thrown(Discard::Unknown);  // noise, MAVLink 1
  size_t total = 0;
  const MessageInfo* info = nullptr;
  const Head h = headOf(w, n, &total, &info);
  if (h == Head::BadFlags) return thrown(Discard::Unknown);
  if (h == Head::TooLong) return thrown(Discard::Length);
  if (h == Head::NeedMore) return final ? thrown(Discard::Length) : Step{Kind::NeedMore, 0};
  if (h == Head::Known && n >= total) {
    if (!verified(w, n, pos)) return thrown(Discard::Crc);
    _stats.messageBytes += total;
    _inUnknownRun = false;
    return Step{Kind::Good, total};
  }
  // Unverifiable (an id we do not know) or not whole yet: its length is not trusted while
  // a frame whose CRC checks starts inside it.
  if (verifiedIn(w, n, pos, 1, total) != 0)
    return thrown(h == Head::Known ? Discard::Length : Discard::Unknown);
  if (n < total) return final ? thrown(Discard::Length) : Step{Kind::NeedMore, 0};
  // A whole frame of an unknown id. On a stream, a frame starting inside it that is not
  // whole yet may still check: wait for it, unless a checked frame after it (and so inside
  // it) already shows it false.
  if (!final) {
    for (size_t p = 1; p < total; ++p) {
      if (w[p] != kStx) continue;
      size_t t = 0;
      const MessageInfo* i = nullptr;
      const Head hp = headOf(w + p, n - p, &t, &i);
      if (hp == Head::NeedMore || (hp == Head::Known && n - p < t)) {
        if (verifiedIn(w, n, pos, p + 1, n) == 0) return Step{Kind::NeedMore, 0};
        break;
      }
    }
  }
  ++_stats.ignored;
  _stats.ignoredBytes += total;
  _inUnknownRun = false;
  return Step{Kind::Foreign, total};
}

void Parser::reset() {
  if (_n > 0) discard(_n, Discard::Length);  // a frame the lost line cut
  _streamPos += _n;                          // positions are never reused: the cache stays right
  _n = 0;
  _inUnknownRun = false;
}

bool Parser::push(uint8_t byte, Message* out) {
  if (_n == kWindowBytes) {  // cannot happen (step decides within a window); never overrun
    discard(1, Discard::Unknown);
    std::memmove(_buf, _buf + 1, --_n);
    ++_streamPos;
  }
  _buf[_n++] = byte;
  return next(out);
}

bool Parser::next(Message* out) {
  while (_n > 0) {
    const Step s = step(_buf, _n, _streamPos, false);
    if (s.kind == Kind::NeedMore) return false;
    if (s.kind == Kind::Good) {
      ++_stats.messages;
      copyMessage(_buf, out);
    }
    std::memmove(_buf, _buf + s.bytes, _n - s.bytes);
    _n -= s.bytes;
    _streamPos += s.bytes;
    if (s.kind == Kind::Good) return true;
  }
  return false;
}

bool Parser::nextInDatagram(const uint8_t* data, size_t n, size_t* offset, Message* out) {
  if (*offset == 0) {  // a new datagram: its own positions, no run carried over
    _datagramBase = _datagramPos;
    _datagramPos += n + kCacheSlots;
    _inUnknownRun = false;
  }
  size_t at = *offset;
  while (at < n) {
    const Step s = step(data + at, n - at, _datagramBase + at, true);
    if (s.kind == Kind::Good) {
      ++_stats.messages;
      copyMessage(data + at, out);
      *offset = at + s.bytes;
      return true;
    }
    at += s.bytes;
  }
  *offset = n;
  return false;
}

}  // namespace cuetrack::platform::mavlink
