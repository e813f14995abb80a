// SerialPort (termios) over a real pseudo-terminal pair made by socat: data both
// ways, raw 8-bit bytes untouched, clear errors, peer loss and reopen.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>

#include "Process.hpp"
#include "Skip.hpp"
#include "cuetrack/platform/linux/SerialPort.hpp"

using namespace cuetrack::platform;
using cuetrack::test::PtyPair;
using cuetrack::test::waitFor;

namespace {

// Reads until `want` bytes arrived or 3 s passed.
size_t readAll(SerialPort& p, uint8_t* buf, size_t want) {
  size_t got = 0;
  waitFor(
      [&] {
        const IoResult r = p.read(buf + got, want - got, 20);
        if (r.status == IoStatus::Ok) got += r.bytes;
        return got >= want || r.status != IoStatus::Ok;
      },
      3000);
  return got;
}

bool haveSocat() {
  return cuetrack::test::fileExists("/usr/bin/socat");
}

}  // namespace

TEST_CASE("bad serial arguments give one line naming the device") {
  SerialPort p;
  REQUIRE_FALSE(p.open("/nonexistent/ttyX", 115200));
  CHECK(std::string(p.error()).find("/nonexistent/ttyX: cannot open") == 0);
  REQUIRE_FALSE(p.open("/dev/null", 115200));
  CHECK(std::string(p.error()).find("/dev/null: not a serial port") == 0);
  REQUIRE_FALSE(p.open("/dev/null", 12345));
  CHECK(std::string(p.error()).find("unsupported baud rate 12345") != std::string::npos);
  CHECK(SerialPort::baudSupported(9600));
  CHECK(SerialPort::baudSupported(921600));
  CHECK_FALSE(SerialPort::baudSupported(300));
}

TEST_CASE("bytes cross a pty pair both ways, all 256 values intact") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  PtyPair pty;
  REQUIRE(pty.start());
  SerialPort a, b;
  REQUIRE(a.open(pty.a(), 921600));
  REQUIRE(b.open(pty.b(), 921600));
  uint8_t all[256];
  for (int i = 0; i < 256; ++i) all[i] = static_cast<uint8_t>(i);
  REQUIRE(a.write(all, sizeof all).bytes == sizeof all);
  uint8_t got[256] = {};
  REQUIRE(readAll(b, got, sizeof got) == sizeof got);
  REQUIRE(std::memcmp(all, got, sizeof all) == 0);  // raw: no CR/LF, XON/XOFF or echo games
  REQUIRE(b.write(all + 10, 5).bytes == 5);
  REQUIRE(readAll(a, got, 5) == 5);
  CHECK(got[0] == 10);
  // Nothing to read: returns after the timeout with 0 bytes, still open.
  const IoResult idle = a.read(got, sizeof got, 10);
  CHECK(idle.status == IoStatus::Ok);
  CHECK(idle.bytes == 0);
}

TEST_CASE("when the peer goes away the port reports Closed, then reopens when it returns") {
  if (!haveSocat()) {
    CUETRACK_SKIP("socat not installed");
  }
  PtyPair pty;
  REQUIRE(pty.start());
  SerialPort a;
  REQUIRE(a.open(pty.a(), 115200));
  pty.stop();
  uint8_t buf[8] = {1, 2, 3};
  IoStatus s = IoStatus::Ok;
  REQUIRE(waitFor(
      [&] {
        s = a.write(buf, 3).status;
        if (s == IoStatus::Ok) s = a.read(buf, sizeof buf, 10).status;
        return s == IoStatus::Closed;
      },
      3000));
  CHECK_FALSE(a.isOpen());
  CHECK(std::string(a.error()).find(pty.a()) == 0);
  CHECK_FALSE(a.reopen());  // links gone
  REQUIRE(pty.start());
  REQUIRE(a.reopen());
  SerialPort b;
  REQUIRE(b.open(pty.b(), 115200));
  REQUIRE(a.write(buf, 3).bytes == 3);
  uint8_t got[3];
  REQUIRE(readAll(b, got, 3) == 3);
}
