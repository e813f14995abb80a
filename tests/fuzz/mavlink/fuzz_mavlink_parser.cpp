// Any bytes into our MAVLink 2 parser: no crash, no overrun, the stats add up, and every
// message it accepts re-encodes to a frame that parses back to the same header and
// payload. Then the same bytes into MavlinkLink: every start it asks for is in range,
// and it never sends more ACKs than it read commands.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>

#include "cuetrack/platform/fake/FakeClock.hpp"
#include "cuetrack/platform/fake/FakeSerial.hpp"
#include "cuetrack/platform/fake/MemoryReporter.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"

using namespace cuetrack::platform;
using namespace cuetrack::platform::mavlink;

namespace {

bool unit(float v) {
  return std::isfinite(v) && v >= 0.f && v <= 1.f;
}

struct Control final : LinkControl {
  int starts = 0;
  uint32_t lastToken = 0;
  void requestStart(const StartRequest& r) override {
    if (r.kind == StartRequest::Kind::BoxNormalised &&
        (!unit(r.box.x) || !unit(r.box.y) || !(r.box.w > 0.f) || !(r.box.h > 0.f) ||
         r.box.x + r.box.w > 1.0001f || r.box.y + r.box.h > 1.0001f))
      abort();
    if (r.kind == StartRequest::Kind::PointNormalised &&
        (!unit(r.pointX) || !unit(r.pointY) || !unit(r.radius)))
      abort();
    ++starts;
    lastToken = r.token;
  }
  void requestReset() override {}
  void requestStop() override {}
};

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Parser p;
  uint32_t messages = 0, commands = 0;
  for (size_t i = 0; i < size; ++i) {
    Message m;
    if (!p.push(data[i], &m)) continue;
    ++messages;
    if (m.header.msgId == kMsgCommandLong || m.header.msgId == kMsgCommandInt) ++commands;
    const MessageInfo* info = messageInfo(m.header.msgId);
    if (info == nullptr || m.len > info->payloadBytes) abort();
    uint8_t wire[kMaxFrameBytes];
    const size_t n = encodeFrame(m.header, m.payload, info->payloadBytes, wire, sizeof wire);
    if (n == 0) abort();
    Parser again;
    Message back;
    bool got = false;
    for (size_t k = 0; k < n; ++k) got = again.push(wire[k], &back);
    if (!got || back.header.msgId != m.header.msgId || back.header.seq != m.header.seq ||
        back.header.sysId != m.header.sysId || back.header.compId != m.header.compId ||
        std::memcmp(back.payload, m.payload, sizeof m.payload) != 0)
      abort();
  }
  if (p.stats().messages != messages) abort();

  // The link: fed in slices that fit the cable, polled after each.
  FakeClock clock(1000);
  FakeSerialCable cable;
  MemoryReporter reporter;
  MavlinkLink link(cable.a(), clock, reporter, LinkConfig{});
  Control control;
  LinkStatus status;
  Parser host;
  uint32_t acks = 0;
  size_t fed = 0;
  while (fed < size) {
    const IoResult w = cable.b().write(data + fed, size - fed);
    fed += w.bytes;
    link.poll(control, status);
    if (control.starts > 0) link.answerStart(control.lastToken, StartOutcome::Started);
    uint8_t buf[1024];
    for (;;) {
      const IoResult r = cable.b().read(buf, sizeof buf, 0);
      if (r.bytes == 0) break;
      for (size_t k = 0; k < r.bytes; ++k) {
        Message m;
        if (host.push(buf[k], &m) && m.header.msgId == kMsgCommandAck) ++acks;
      }
    }
    clock.advanceUs(1000);
  }
  if (host.stats().badCrc != 0 || host.stats().badFrame != 0) abort();  // we frame right
  if (acks > commands) abort();
  return 0;
}
