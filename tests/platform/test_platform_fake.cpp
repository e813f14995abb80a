// The fakes behave like the real things they stand in for.
#include <catch2/catch.hpp>

#include "cuetrack/platform/fake/FakeClock.hpp"
#include "cuetrack/platform/fake/FakeSerial.hpp"
#include "cuetrack/platform/fake/MemoryReporter.hpp"
#include "cuetrack/platform/fake/MemorySink.hpp"

using namespace cuetrack::platform;

TEST_CASE("FakeClock moves only when told") {
  FakeClock c(5);
  CHECK(c.nowUs() == 5);
  c.advanceUs(10);
  CHECK(c.nowUs() == 15);
  c.setUs(1);
  CHECK(c.nowUs() == 1);
}

TEST_CASE("FakeSerialCable carries bytes both ways, fills up, unplugs and replugs") {
  static FakeSerialCable cable;  // 8 KiB of rings: keep off the stack
  const uint8_t msg[] = {1, 2, 3, 0, 5};
  uint8_t buf[16];
  REQUIRE(cable.a().write(msg, sizeof msg).bytes == sizeof msg);
  IoResult r = cable.b().read(buf, sizeof buf, 100);
  REQUIRE(r.status == IoStatus::Ok);
  REQUIRE(r.bytes == sizeof msg);
  CHECK(buf[4] == 5);
  REQUIRE(cable.b().write(msg, 2).bytes == 2);
  REQUIRE(cable.a().read(buf, sizeof buf, 0).bytes == 2);

  cable.setCapacityAtoB(3);
  r = cable.a().write(msg, sizeof msg);
  CHECK(r.status == IoStatus::Ok);
  CHECK(r.bytes == 3);  // short write
  CHECK(cable.a().write(msg, sizeof msg).status == IoStatus::WouldBlock);
  cable.setCapacityAtoB(FakeSerialCable::kRingBytes);

  cable.setPlugged(false);
  CHECK(cable.a().write(msg, 1).status == IoStatus::Closed);
  CHECK_FALSE(cable.a().isOpen());
  CHECK_FALSE(cable.a().reopen());
  CHECK(std::string(cable.a().error()).find("fake-a") != std::string::npos);
  cable.setPlugged(true);
  REQUIRE(cable.a().reopen());
  REQUIRE(cable.a().write(msg, 1).bytes == 1);
  REQUIRE(cable.b().read(buf, sizeof buf, 0).bytes == 1);  // old bytes were lost
}

TEST_CASE("MemorySink keeps messages and fails on request") {
  static MemorySink sink;
  ctp_track_t t{};
  t.seq = 4;
  REQUIRE(sink.write(t));
  REQUIRE(sink.size() == 1);
  CHECK(sink.at(0).seq == 4);
  sink.setFailing(true);
  REQUIRE_FALSE(sink.write(t));
  CHECK(std::string(sink.error()).find("memory") != std::string::npos);
}

TEST_CASE("MemoryReporter counts lines") {
  static MemoryReporter rep;
  rep.report("serial x: peer gone");
  rep.report("serial x: reconnected");
  CHECK(rep.count() == 2);
  CHECK(rep.countContaining("serial x") == 2);
  CHECK(rep.countContaining("reconnected") == 1);
}
