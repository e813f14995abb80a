// SerialPort (termios) over a real pseudo-terminal pair made by socat: data both
// ways, raw 8-bit bytes untouched, clear errors, peer loss and reopen.
#include <catch2/catch.hpp>

#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <cstring>
#include <string>

#include "Process.hpp"
#include "Skip.hpp"
#include "cuetrack/platform/linux/PortLock.hpp"
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

namespace {
// A private lock folder per test: the tests do not touch /run/lock.
struct LockDir {
  char path[64];
  LockDir() {
    std::snprintf(path, sizeof path, "/tmp/cuetrack-lock-XXXXXX");
    REQUIRE(mkdtemp(path) != nullptr);
  }
  ~LockDir() {
    const std::string cmd = std::string("rm -rf ") + path;
    if (std::system(cmd.c_str()) != 0) std::fprintf(stderr, "could not remove %s\n", path);
  }
};

void writeLockFile(const std::string& path, long pid) {
  FILE* f = std::fopen(path.c_str(), "w");
  REQUIRE(f != nullptr);
  std::fprintf(f, "%10ld\n", pid);
  std::fclose(f);
}
}  // namespace

TEST_CASE("lock file names: below /dev, slashes as underscores") {
  char out[128];
  REQUIRE(PortLock::lockPathFor("/run/lock", "/dev/ttyUSB0", out, sizeof out));
  CHECK(std::string(out) == "/run/lock/LCK..ttyUSB0");
  REQUIRE(PortLock::lockPathFor("/run/lock", "/dev/pts/7", out, sizeof out));
  CHECK(std::string(out) == "/run/lock/LCK..pts_7");
  CHECK_FALSE(PortLock::lockPathFor("/run/lock", "/dev/ttyUSB0", out, 12));
}

TEST_CASE("a second opener of one port is refused, naming the holder; stale locks are replaced") {
  if (!haveSocat()) CUETRACK_SKIP("socat not installed");
  PtyPair pty;
  REQUIRE(pty.start());
  LockDir dir;
  char lockPath[256];
  REQUIRE(PortLock::lockPathFor(dir.path, pty.a(), lockPath, sizeof lockPath));
  const std::string lock = lockPath;

  SerialPort first(dir.path);
  REQUIRE(first.open(pty.a(), 115200));
  CHECK(cuetrack::test::fileExists(lock.c_str()));
  char text[64] = "";
  REQUIRE(cuetrack::test::readFile(lock.c_str(), text, sizeof text));
  CHECK(std::strtol(text, nullptr, 10) == static_cast<long>(getpid()));

  // The same process again: the lock file is ours, the device's flock refuses.
  SerialPort second(dir.path);
  CHECK_FALSE(second.open(pty.a(), 115200));
  CHECK(std::string(second.error()).find(std::string(pty.a()) + ": in use by") == 0);
  first.close();
  CHECK_FALSE(cuetrack::test::fileExists(lock.c_str()));  // released with the port
  REQUIRE(second.open(pty.a(), 115200));
  second.close();
  // reopen() (the link's retry after a vanished device) takes the lock file again.
  REQUIRE(second.reopen());
  CHECK(cuetrack::test::fileExists(lock.c_str()));
  second.close();

  SECTION("a lock file whose process holds the device names its PID") {
    // Another program with the port open (as minicom would, without flock): a child that
    // opens it, says so through a pipe, and waits for the pipe to close.
    int ready[2], done[2];
    REQUIRE(::pipe(ready) == 0);
    REQUIRE(::pipe(done) == 0);
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) {
      ::close(ready[0]);
      ::close(done[1]);  // else its own write end keeps the pipe open for ever
      const int fd = ::open(pty.a(), O_RDWR | O_NOCTTY);
      char c = fd >= 0 ? 'y' : 'n';
      if (::write(ready[1], &c, 1) != 1) _exit(1);
      while (::read(done[0], &c, 1) > 0) {
      }
      _exit(0);
    }
    ::close(ready[1]);
    ::close(done[0]);
    char c = 0;
    REQUIRE(::read(ready[0], &c, 1) == 1);
    REQUIRE(c == 'y');
    writeLockFile(lock, static_cast<long>(child));
    SerialPort p(dir.path);
    CHECK_FALSE(p.open(pty.a(), 115200));
    CHECK(std::string(p.error()) == std::string(pty.a()) + ": in use by process " +
                                        std::to_string(child) + " (lock file " + lock + ")");
    CHECK(cuetrack::test::fileExists(lock.c_str()));  // not ours to remove
    ::close(done[1]);
    ::close(ready[0]);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);
  }
  SECTION("a lock file naming a live process without the device is stale: replaced, said") {
    // A planted file naming PID 1, or our parent (alive, but not holding the pty).
    for (const long planted : {1L, static_cast<long>(getppid())}) {
      writeLockFile(lock, planted);
      SerialPort p(dir.path);
      REQUIRE(p.open(pty.a(), 115200));
      CHECK(std::string(p.notice())
                .find(std::string(pty.a()) + ": replaced the stale lock file " + lock +
                      " (process " + std::to_string(planted)) == 0);
      REQUIRE(cuetrack::test::readFile(lock.c_str(), text, sizeof text));
      CHECK(std::strtol(text, nullptr, 10) == static_cast<long>(getpid()));
      p.close();
    }
  }
  SECTION("a lock file whose process is gone is stale and replaced") {
    const pid_t child = fork();
    REQUIRE(child >= 0);
    if (child == 0) _exit(0);
    int status = 0;
    REQUIRE(waitpid(child, &status, 0) == child);  // reaped: that PID is dead
    writeLockFile(lock, static_cast<long>(child));
    SerialPort p(dir.path);
    REQUIRE(p.open(pty.a(), 115200));
    CHECK(std::string(p.notice()).find("(process " + std::to_string(child) + " is gone)") !=
          std::string::npos);
    REQUIRE(cuetrack::test::readFile(lock.c_str(), text, sizeof text));
    CHECK(std::strtol(text, nullptr, 10) == static_cast<long>(getpid()));
  }
  SECTION("a folder at the lock's path is said as what it is, not as a replaced lock") {
    REQUIRE(::mkdir(lock.c_str(), 0755) == 0);
    SerialPort p(dir.path);
    REQUIRE(p.open(pty.a(), 115200));  // flock still keeps the port ours
    CHECK(std::string(p.notice()) == std::string(pty.a()) + ": " + lock +
                                         " is not a lock file (a folder or a link): the port is "
                                         "used without a lock; remove it so the next run can "
                                         "lock the port");
    p.close();
    CHECK(::rmdir(lock.c_str()) == 0);  // left as it was
  }
  SECTION("a lock folder we cannot use is no error; flock still keeps the port ours") {
    SerialPort p("/nonexistent/lockdir"), q("/nonexistent/lockdir");
    REQUIRE(p.open(pty.a(), 115200));
    CHECK_FALSE(q.open(pty.a(), 115200));
    CHECK(std::string(q.error()).find("in use by another program (locked; holder unknown)") !=
          std::string::npos);
  }
}
