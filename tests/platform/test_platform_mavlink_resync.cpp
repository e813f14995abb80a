// The parser's resynchronisation (issue 56): no bytes in front of a command can swallow it,
// on a byte stream (serial) or in a datagram (UDP). The findings as tests, then a property
// test over generated prefixes. The official library's view of the same bytes is in
// test_platform_mavlink_official.
#include <catch2/catch.hpp>

#include <cstring>
#include <memory>
#include <vector>

#include "MavlinkPrefixes.hpp"
#include "cuetrack/platform/fake/FakeClock.hpp"
#include "cuetrack/platform/fake/FakeSerial.hpp"
#include "cuetrack/platform/fake/MemoryReporter.hpp"
#include "cuetrack/platform/mavlink/MavlinkLink.hpp"

using namespace cuetrack;
using namespace cuetrack::platform;
using namespace cuetrack::platform::mavlink;
using cuetrack::test::numberedCommand;
using cuetrack::test::PrefixGenerator;

namespace {

#if defined(__SANITIZE_ADDRESS__) || defined(__aarch64__) || defined(__arm__)
// AddressSanitizer and qemu (the cross presets) run this about 12 times slower (2,000 in
// 0.6 s under each): fewer there. The host runs the bar.
constexpr uint32_t kPrefixes = 2000;
#else
constexpr uint32_t kPrefixes = 10000;  // at least 10,000; 0.2-0.3 s on the host
#endif

bool isNumbered(const Message& m, uint32_t number) {
  if (m.header.msgId != kMsgCommandLong || m.header.sysId != 255 ||
      m.header.seq != static_cast<uint8_t>(number))
    return false;
  return unpackCommandLong(m.payload).param[0] == static_cast<float>(number);
}

std::vector<uint8_t> join(std::vector<uint8_t> a, const std::vector<uint8_t>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

struct NoControl final : LinkControl {
  int resets = 0;
  void requestStart(const StartRequest&) override {}
  void requestReset() override { ++resets; }
  void requestStop() override {}
};

// A datagram stream in memory: each read hands out one queued datagram.
struct MemoryDatagrams final : ByteStream {
  std::vector<std::vector<uint8_t>> in;
  size_t next = 0;
  Parser peer;
  int acks = 0;
  IoResult read(uint8_t* buf, size_t cap, int) override {
    if (next == in.size()) return {IoStatus::Ok, 0};
    const auto& d = in[next++];
    const size_t n = d.size() < cap ? d.size() : cap;
    std::memcpy(buf, d.data(), n);
    return {IoStatus::Ok, n};
  }
  IoResult write(const uint8_t* d, size_t n) override {
    size_t at = 0;
    Message m;
    while (peer.nextInDatagram(d, n, &at, &m)) acks += m.header.msgId == kMsgCommandAck;
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

// The link's answers to `bytes`: written to a serial cable in one write, or sent as one
// datagram; rx-errors after.
struct Answered {
  int acks = 0;
  uint32_t rxErrors = 0;
};
Answered overSerial(const std::vector<uint8_t>& bytes) {
  FakeClock clock(1000);
  FakeSerialCable cable;
  MemoryReporter reporter;
  auto link = std::make_unique<MavlinkLink>(cable.a(), clock, reporter, LinkConfig{});
  NoControl control;
  REQUIRE(cable.b().write(bytes.data(), bytes.size()).bytes == bytes.size());
  link->poll(control, LinkStatus{});
  Parser host;
  Answered a;
  uint8_t buf[4096];
  for (IoResult r; (r = cable.b().read(buf, sizeof buf, 0)).bytes > 0;)
    for (size_t i = 0; i < r.bytes; ++i) {
      Message m;
      if (host.push(buf[i], &m)) a.acks += m.header.msgId == kMsgCommandAck;
    }
  a.rxErrors = link->stats().rxErrors;
  return a;
}
Answered overUdp(const std::vector<uint8_t>& datagram) {
  FakeClock clock(1000);
  MemoryDatagrams udp;
  udp.in.push_back(datagram);
  MemoryReporter reporter;
  auto link = std::make_unique<MavlinkLink>(udp, clock, reporter, LinkConfig{});
  NoControl control;
  link->poll(control, LinkStatus{});
  return {udp.acks, link->stats().rxErrors};
}

}  // namespace

TEST_CASE("resync: three bytes in front of a command no longer swallow it (issue 56, 1)") {
  const auto cmd = numberedCommand(1);
  for (const std::vector<uint8_t>& head :
       {std::vector<uint8_t>{kStx, 0x00, 0x00}, std::vector<uint8_t>{kStx, 0x21, 0x00},
        std::vector<uint8_t>{kStx, 0xFF, 0x00}}) {
    INFO("FD " << int(head[1]) << " " << int(head[2]) << " in front");
    const auto bytes = join(head, cmd);
    const Answered serial = overSerial(bytes), udp = overUdp(bytes);
    CHECK(serial.acks == 1);
    CHECK(udp.acks == 1);
    CHECK(serial.rxErrors == 1);  // the three bytes, discarded and counted
    CHECK(udp.rxErrors == 1);
  }
  // FD FF 00 before six commands on serial: all six answered (0 of 6 before).
  std::vector<uint8_t> six = {kStx, 0xFF, 0x00};
  for (uint32_t i = 0; i < 6; ++i) six = join(six, numberedCommand(i));
  CHECK(overSerial(six).acks == 6);
  CHECK(overUdp(six).acks == 6);
}

TEST_CASE("resync: a frame cut after any number of bytes never takes the good frame after it") {
  const auto good = numberedCommand(2);
  int keptSerial = 0, keptUdp = 0, cuts = 0;
  for (size_t cut = 1; cut < good.size(); ++cut) {  // 1..44 bytes of a 45-byte command
    ++cuts;
    const auto bytes =
        join(std::vector<uint8_t>(good.begin(), good.begin() + static_cast<long>(cut)),
             numberedCommand(3));
    const Answered serial = overSerial(bytes), udp = overUdp(bytes);
    keptSerial += serial.acks == 1;
    keptUdp += udp.acks == 1;
    INFO("cut after " << cut << " bytes");
    CHECK(serial.rxErrors >= 1);  // the cut frame is counted, never silent
    CHECK(udp.rxErrors >= 1);
  }
  CHECK(keptSerial == cuts);
  CHECK(keptUdp == cuts);
}

TEST_CASE("resync: a router's frames of messages we do not know still pass whole") {
  // Another component's message (id 0x012345), its payload full of start bytes and
  // headers that check nothing: passed whole, ignored, no error; the command after it answered.
  std::vector<uint8_t> foreign = {kStx, 60, 0, 0, 9, 1, 1, 0x45, 0x23, 0x01};
  for (int i = 0; i < 60; ++i) foreign.push_back(i % 5 == 0 ? kStx : static_cast<uint8_t>(i));
  foreign.push_back(0x12);
  foreign.push_back(0x34);
  Parser p;
  size_t at = 0;
  Message m;
  const auto datagram = join(foreign, numberedCommand(4));
  REQUIRE(p.nextInDatagram(datagram.data(), datagram.size(), &at, &m));
  CHECK(isNumbered(m, 4));
  CHECK(p.stats().ignored == 1);
  CHECK(p.stats().ignoredBytes == foreign.size());
  CHECK(p.stats().totalErrors() == 0);
  Parser s;
  int got = 0;
  for (uint8_t b : datagram)
    for (bool r = s.push(b, &m); r; r = s.next(&m)) got += isNumbered(m, 4);
  CHECK(got == 1);
  CHECK(s.stats().ignored == 1);
  CHECK(s.stats().totalErrors() == 0);
  CHECK(overSerial(datagram).rxErrors == 0);
}

TEST_CASE(
    "resync property: after any generated prefix the command is decoded, stream and datagram") {
  PrefixGenerator gen(56);
  Parser stream, datagrams;
  uint64_t streamBytes = 0;
  uint32_t keptStream = 0, keptDatagram = 0;
  std::vector<uint32_t> lost;
  for (uint32_t i = 0; i < kPrefixes; ++i) {
    const auto bytes = join(gen.next(), numberedCommand(i));
    streamBytes += bytes.size();
    // One continuous stream: what came before carries over, and the command must be out by
    // its own last byte (a quiet line after it must not hold it).
    bool got = false;
    Message m;
    for (uint8_t b : bytes)
      for (bool r = stream.push(b, &m); r; r = stream.next(&m)) got = got || isNumbered(m, i);
    keptStream += got;
    if (!got && lost.size() < 8) lost.push_back(i);
    // The same bytes as one datagram.
    size_t at = 0;
    got = false;
    while (datagrams.nextInDatagram(bytes.data(), bytes.size(), &at, &m))
      got = got || isNumbered(m, i);
    keptDatagram += got;
  }
  std::string lostList;
  for (uint32_t i : lost) lostList += " " + std::to_string(i);
  INFO("lost on the stream:" << lostList);
  CHECK(keptStream == kPrefixes);
  CHECK(keptDatagram == kPrefixes);
  // Every byte is in a message, another component's frame, or counted as discarded.
  const ParserStats& s = stream.stats();
  CHECK(s.messageBytes + s.ignoredBytes + s.discardedBytes[0] + s.discardedBytes[1] +
            s.discardedBytes[2] + stream.held() ==
        streamBytes);
  CHECK(s.badCrc() > 0);
  CHECK(s.badLength() > 0);
  CHECK(s.badUnknown() > 0);
  CHECK(s.ignored > 0);
}
