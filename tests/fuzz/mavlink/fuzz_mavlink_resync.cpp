// Any bytes, then a valid command: the command is decoded, by the parser on a byte stream
// (fed to it whole, by its own last byte) and in one datagram; and every byte is in a
// message, another component's frame, or counted as discarded (issue 56). The oracle of
// the resynchronisation: no byte sequence in front of a command can swallow it.
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "cuetrack/platform/mavlink/MavlinkCodec.hpp"
#include "cuetrack/platform/mavlink/MavlinkMessages.hpp"

using namespace cuetrack::platform::mavlink;

namespace {

constexpr size_t kMaxInput = 4096;

size_t command(uint8_t* out) {
  CommandLong c;
  c.command = kCmdCameraStopTracking;
  c.param[0] = 12345.f;
  c.targetSystem = 1;
  c.targetComponent = 100;
  uint8_t p[40];
  Header h;
  h.seq = 0x5A;
  h.sysId = 255;
  h.compId = 190;
  h.msgId = kMsgCommandLong;
  return encodeFrame(h, p, pack(c, p), out, kMaxFrameBytes);
}

bool isTheCommand(const Message& m) {
  return m.header.msgId == kMsgCommandLong && m.header.sysId == 255 && m.header.compId == 190 &&
         m.header.seq == 0x5A && unpackCommandLong(m.payload).param[0] == 12345.f;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size > kMaxInput) return 0;
  static uint8_t bytes[kMaxInput + kMaxFrameBytes];
  std::memcpy(bytes, data, size);
  const size_t n = size + command(bytes + size);

  Parser stream;
  Message m;
  bool got = false;
  for (size_t i = 0; i < n; ++i)
    for (bool r = stream.push(bytes[i], &m); r; r = stream.next(&m)) got = got || isTheCommand(m);
  if (!got) abort();  // the stream parser lost the trailing command
  const ParserStats& s = stream.stats();
  if (s.messageBytes + s.ignoredBytes + s.discardedBytes[0] + s.discardedBytes[1] +
          s.discardedBytes[2] + stream.held() !=
      n)
    abort();  // a byte vanished uncounted

  Parser datagram;
  size_t at = 0;
  got = false;
  while (datagram.nextInDatagram(bytes, n, &at, &m)) got = got || isTheCommand(m);
  if (!got) abort();  // lost in the datagram
  const ParserStats& d = datagram.stats();
  if (d.messageBytes + d.ignoredBytes + d.discardedBytes[0] + d.discardedBytes[1] +
          d.discardedBytes[2] !=
      n)
    abort();
  return 0;
}
