// Any bytes into our MAVLink 2 parser: no crash, no overrun, the stats add up, and every
// message it accepts re-encodes to a frame that parses back to the same header and
// payload. The same bytes cut into datagrams (each chunk's first byte gives its length)
// through the datagram parser: the same checks, and each datagram gives the same messages
// as in a fresh parser (nothing carries over). Then the same bytes into MavlinkLink: every
// start it asks for is in range, and it never sends more ACKs than it read commands.
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <memory>

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

void checkReencodes(const Message& m) {
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

// A UDP socket's stand-in: reads hand out the datagrams queued, one per read; what the
// link writes is parsed as the peer would, datagram by datagram.
struct Datagrams final : ByteStream {
  const uint8_t* in[4096]{};
  size_t inLen[4096]{};
  size_t queued = 0, next = 0;
  Parser peer;
  uint32_t acks = 0;
  IoResult read(uint8_t* buf, size_t cap, int) override {
    if (next == queued) return {IoStatus::Ok, 0};
    const size_t n = inLen[next] < cap ? inLen[next] : cap;
    std::memcpy(buf, in[next++], n);
    return {IoStatus::Ok, n};
  }
  IoResult write(const uint8_t* d, size_t n) override {
    size_t at = 0;
    Message m;
    uint32_t got = 0;
    while (peer.nextInDatagram(d, n, &at, &m)) {
      ++got;
      acks += m.header.msgId == kMsgCommandAck;
    }
    if (got != 1) abort();  // one whole message a datagram
    return {IoStatus::Ok, n};
  }
  bool waitWritable(int) override { return true; }
  bool isOpen() const override { return true; }
  bool reopen() override { return true; }
  void close() override {}
  const char* error() const override { return ""; }
  const char* name() const override { return "datagrams"; }
  bool datagrams() const override { return true; }
};

void datagrams(const uint8_t* data, size_t size) {
  Parser shared;
  uint32_t messages = 0, commands = 0;
  auto owned = std::make_unique<Datagrams>();  // 64 KiB of pointers: not on the stack
  Datagrams& stream = *owned;
  size_t at = 0;
  while (at < size) {
    const size_t len = data[at] * 2u;
    const uint8_t* d = data + at + 1;
    const size_t n = len < size - at - 1 ? len : size - at - 1;
    at += 1 + n;
    Parser fresh;
    size_t offShared = 0, offFresh = 0;
    for (;;) {
      Message a, b;
      const size_t before = offShared;
      const bool gotA = shared.nextInDatagram(d, n, &offShared, &a);
      const bool gotB = fresh.nextInDatagram(d, n, &offFresh, &b);
      if (gotA != gotB || offShared != offFresh || offShared > n || (gotA && offShared <= before))
        abort();
      if (!gotA) break;
      if (a.header.msgId != b.header.msgId || a.header.seq != b.header.seq ||
          a.header.sysId != b.header.sysId || a.header.compId != b.header.compId ||
          std::memcmp(a.payload, b.payload, sizeof a.payload) != 0)
        abort();
      checkReencodes(a);
      ++messages;
      if (a.header.msgId == kMsgCommandLong || a.header.msgId == kMsgCommandInt) ++commands;
    }
    if (n > 0 && stream.queued < 4096) {
      stream.in[stream.queued] = d;
      stream.inLen[stream.queued++] = n;
    }
  }
  if (shared.stats().messages != messages) abort();

  // The link over those datagrams, polled until it has read them all.
  FakeClock clock(1000);
  MemoryReporter reporter;
  auto link = std::make_unique<MavlinkLink>(stream, clock, reporter, LinkConfig{});
  Control control;
  for (int polls = 0; stream.next < stream.queued && polls < 4096; ++polls) {
    link->poll(control, LinkStatus{});
    if (control.starts > 0) link->answerStart(control.lastToken, StartOutcome::Started);
    clock.advanceUs(1000);
  }
  if (stream.next != stream.queued) abort();  // a poll always reads what waits
  if (stream.peer.stats().totalErrors() != 0) abort();
  if (stream.acks > commands) abort();
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  Parser p;
  uint32_t messages = 0, commands = 0;
  for (size_t i = 0; i < size; ++i) {
    Message m;
    if (!p.push(data[i], &m)) continue;
    ++messages;
    if (m.header.msgId == kMsgCommandLong || m.header.msgId == kMsgCommandInt) ++commands;
    checkReencodes(m);
  }
  if (p.stats().messages != messages) abort();
  datagrams(data, size);

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
  if (host.stats().totalErrors() != 0) abort();  // we frame right
  if (acks > commands) abort();
  return 0;
}
