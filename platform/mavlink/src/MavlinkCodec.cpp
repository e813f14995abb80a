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

// A frame at the start of buf (buf[0] is the start byte), judged on the n bytes there.
enum class Check : uint8_t { NeedMore, Good, BadCrc, BadFrame, Ignored };
Check checkFrame(const uint8_t* buf, size_t n, size_t* total) {
  if (n >= 3 && (buf[2] & ~kIncompatSigned) != 0) return Check::BadFrame;
  if (n < kHeaderBytes) return Check::NeedMore;
  const size_t len = buf[1];
  const MessageInfo* info = messageInfo(msgIdOf(buf));
  if (info != nullptr && len > info->payloadBytes) return Check::BadFrame;
  *total = kHeaderBytes + len + kCrcBytes + ((buf[2] & kIncompatSigned) ? kSignatureBytes : 0);
  if (n < *total) return Check::NeedMore;
  if (info == nullptr) return Check::Ignored;
  uint16_t crc = crc16(buf + 1, kHeaderBytes - 1 + len);
  crc = crcAccumulate(info->crcExtra, crc);
  const uint16_t got =
      static_cast<uint16_t>(buf[kHeaderBytes + len] | (buf[kHeaderBytes + len + 1] << 8));
  return crc == got ? Check::Good : Check::BadCrc;
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

void Parser::resync() {
  size_t k = 1;
  while (k < _n && _buf[k] != kStx) ++k;
  std::memmove(_buf, _buf + k, _n - k);
  _n -= k;
}

bool Parser::push(uint8_t byte, Message* out) {
  if (_n == 0 && byte != kStx) return false;
  _buf[_n++] = byte;
  for (;;) {
    size_t total = 0;
    const Check c = checkFrame(_buf, _n, &total);
    switch (c) {
      case Check::NeedMore:
        return false;
      case Check::Ignored:
        ++_stats.ignored;
        _n = 0;
        return false;
      case Check::Good:
        ++_stats.messages;
        copyMessage(_buf, out);
        _n = 0;
        return true;
      case Check::BadCrc:
      case Check::BadFrame:
        ++(c == Check::BadCrc ? _stats.badCrc : _stats.badFrame);
        resync();  // the bytes kept may hold (the start of) a good frame: check them again
        if (_n == 0) return false;
        break;
    }
  }
}

bool Parser::nextInDatagram(const uint8_t* data, size_t n, size_t* offset, Message* out) {
  size_t at = *offset;
  while (at < n) {
    if (data[at] != kStx) {  // noise, MAVLink 1: skipped, as on a byte stream
      ++at;
      continue;
    }
    size_t total = 0;
    const Check c = checkFrame(data + at, n - at, &total);
    if (c == Check::Good) {
      ++_stats.messages;
      copyMessage(data + at, out);
      *offset = at + total;
      return true;
    }
    if (c == Check::Ignored) {
      ++_stats.ignored;
      at += total;
      continue;
    }
    // Bad, or cut by the datagram's end (nothing more will come for it): counted, and
    // the next start byte inside it is tried, so a false start cannot hide a good frame.
    ++(c == Check::BadCrc ? _stats.badCrc : _stats.badFrame);
    ++at;
  }
  *offset = n;
  return false;
}

}  // namespace cuetrack::platform::mavlink
