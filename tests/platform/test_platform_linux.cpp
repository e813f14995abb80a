// Linux implementations other than the serial port: file/stdout sinks and their
// errors, the monotonic clock, the stop signals, the reporters.
#include <catch2/catch.hpp>

#include <arpa/inet.h>
#include <fcntl.h>
#include <netinet/in.h>
#include <signal.h>
#include <stdlib.h>
#include <sys/resource.h>
#include <sys/socket.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <future>
#include <string>

#include "LoopbackUdp.hpp"
#include "TempDir.hpp"
#include "cuetrack/platform/linux/FdTrackSink.hpp"
#include "cuetrack/platform/linux/KeyFile.hpp"
#include "cuetrack/platform/linux/MonotonicClock.hpp"
#include "cuetrack/platform/linux/Signals.hpp"
#include "cuetrack/platform/linux/UdpSocket.hpp"

using namespace cuetrack::platform;
using cuetrack::test::LoopbackUdp;

TEST_CASE("a full disk is one line naming the file, not a crash") {
  FdTrackSink lines;
  REQUIRE(lines.openFile("/dev/full", TextFormat::Line));  // opening works...
  ctp_track_t t{};
  REQUIRE_FALSE(lines.write(t));  // ...writing does not
  CHECK(std::string(lines.error()) == "/dev/full: write failed: No space left on device");
  FdTrackSink csv;
  REQUIRE_FALSE(csv.openFile("/dev/full", TextFormat::Csv));  // the header already fails
  FdTrackSink missing;
  REQUIRE_FALSE(missing.openFile("/nonexistent-dir/x.csv", TextFormat::Csv));
  CHECK(std::string(missing.error()).find("/nonexistent-dir/x.csv: cannot create") == 0);
  // A FIFO nobody reads: refused at once instead of blocking open() forever.
  std::remove("platform_fifo");
  REQUIRE(mkfifo("platform_fifo", 0644) == 0);
  FdTrackSink fifo;
  CHECK_FALSE(fifo.openFile("platform_fifo", TextFormat::Csv));
  CHECK(std::string(fifo.error()) == "platform_fifo: cannot create: a FIFO with no reader");
  std::remove("platform_fifo");
}

TEST_CASE("a CSV file gets the header and one row per message") {
  char path[] = "/tmp/cuetrack-sink-XXXXXX";
  const int fd = mkstemp(path);
  REQUIRE(fd >= 0);
  close(fd);
  {
    FdTrackSink sink;
    REQUIRE(sink.openFile(path, TextFormat::Csv));
    ctp_track_t t{};
    t.seq = 1;
    t.state = CTP_STATE_LOST;
    REQUIRE(sink.write(t));
    t.seq = 2;
    REQUIRE(sink.write(t));
  }
  char buf[1024] = "";
  FILE* f = std::fopen(path, "r");
  REQUIRE(f);
  const size_t n = std::fread(buf, 1, sizeof buf - 1, f);
  std::fclose(f);
  unlink(path);
  buf[n] = '\0';
  const std::string text(buf);
  CHECK(text.find("seq,time_us,state,") == 0);
  CHECK(text.find("\n1,0,lost,") != std::string::npos);
  CHECK(text.find("\n2,0,lost,") != std::string::npos);
}

TEST_CASE("the monotonic clock never goes back") {
  MonotonicClock clock;
  uint64_t last = clock.nowUs();
  REQUIRE(last > 0);
  for (int i = 0; i < 1000; ++i) {
    const uint64_t now = clock.nowUs();
    REQUIRE(now >= last);
    last = now;
  }
}

TEST_CASE("SIGTERM and SIGINT only set the stop flag") {
  installStopSignals();
  CHECK_FALSE(stopRequested());
  REQUIRE(raise(SIGTERM) == 0);  // the process survives: the handler only records it
  CHECK(stopRequested());
  CHECK(stopSignal() == SIGTERM);
  REQUIRE(raise(SIGPIPE) == 0);  // ignored: a closed pipe becomes a write error instead
}

TEST_CASE("a disk that fills mid-row leaves whole rows only, and says so") {
  // The file-size limit stands in for a full disk: write() takes what fits, then fails.
  const char* path = "platform_rows.csv";
  const pid_t pid = fork();
  REQUIRE(pid >= 0);
  if (pid == 0) {
    ignoreWriteSignals();
    rlimit lim{};
    lim.rlim_cur = lim.rlim_max = 700;  // bytes: the header and a few rows, then mid-row
    setrlimit(RLIMIT_FSIZE, &lim);
    FdTrackSink csv;
    if (!csv.openFile(path, TextFormat::Csv)) _exit(2);
    ctp_track_t t{};
    for (uint32_t i = 0; i < 100; ++i) {
      t.seq = i;
      if (!csv.write(t))
        _exit(std::string(csv.error()).find("(the partial row was removed)") != std::string::npos
                  ? 0
                  : 3);
    }
    _exit(4);
  }
  int status = 0;
  REQUIRE(waitpid(pid, &status, 0) == pid);
  REQUIRE(WIFEXITED(status));
  CHECK(WEXITSTATUS(status) == 0);
  FILE* f = std::fopen(path, "rb");
  REQUIRE(f != nullptr);
  std::string text;
  char buf[1024];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) text.append(buf, n);
  std::fclose(f);
  std::remove(path);
  REQUIRE_FALSE(text.empty());
  CHECK(text.size() < 700);
  CHECK(text.back() == '\n');  // ends on a whole row
  // Every row has as many fields as the header.
  const auto fields = [](const std::string& line) {
    return std::count(line.begin(), line.end(), ',');
  };
  size_t start = 0, rows = 0;
  const long want = fields(text.substr(0, text.find('\n')));
  while (start < text.size()) {
    const size_t end = text.find('\n', start);
    CHECK(fields(text.substr(start, end - start)) == want);
    start = end + 1;
    ++rows;
  }
  CHECK(rows >= 2);  // the header and at least one row made it
}

TEST_CASE("close() syncs and closes a file, stdout stays open") {
  char path[] = "/tmp/cuetrack-close-XXXXXX";
  const int fd = mkstemp(path);
  REQUIRE(fd >= 0);
  ::close(fd);
  FdTrackSink csv;
  REQUIRE(csv.openFile(path, TextFormat::Csv));
  ctp_track_t t{};
  REQUIRE(csv.write(t));
  CHECK(csv.close());
  CHECK_FALSE(csv.write(t));  // closed: nothing more goes to the file
  CHECK(std::string(csv.error()) == std::string(path) + ": not open");
  std::remove(path);
  FdTrackSink out;
  out.attachStdout(TextFormat::Line);
  CHECK(out.close());  // not ours to close
  CHECK(::fcntl(1, F_GETFD) != -1);
}

TEST_CASE("a file-size limit (ulimit -f) is a write error, not a silent death") {
  // In a child: the limit and the signal disposition are process-wide.
  auto writeOverLimit = [](bool ignore) {
    const pid_t pid = fork();
    REQUIRE(pid >= 0);
    if (pid == 0) {
      if (ignore)
        ignoreWriteSignals();
      else
        signal(SIGXFSZ, SIG_DFL);  // an earlier test's installStopSignals() is inherited
      rlimit lim{};
      lim.rlim_cur = lim.rlim_max = 512;  // bytes
      setrlimit(RLIMIT_FSIZE, &lim);
      FdTrackSink csv;
      if (!csv.openFile("platform_fsize.csv", TextFormat::Csv)) _exit(2);
      ctp_track_t t{};
      for (int i = 0; i < 100; ++i)
        if (!csv.write(t))
          _exit(std::string(csv.error()).find("File too large") != std::string::npos ? 0 : 3);
      _exit(4);
    }
    int status = 0;
    REQUIRE(waitpid(pid, &status, 0) == pid);
    std::remove("platform_fsize.csv");
    return status;
  };
  const int reported = writeOverLimit(true);
  REQUIRE(WIFEXITED(reported));
  CHECK(WEXITSTATUS(reported) == 0);         // the write failed with EFBIG and said so
  const int killed = writeOverLimit(false);  // control: the default disposition kills
  CHECK(WIFSIGNALED(killed));
  CHECK(WTERMSIG(killed) == SIGXFSZ);
}

TEST_CASE("UdpSocket: one datagram per write to a loopback peer, replies read back") {
  LoopbackUdp peerSocket;
  const int peer = peerSocket.fd;
  const char* target = peerSocket.target;
  UdpSocket udp;
  REQUIRE(udp.open(target));
  CHECK(std::string(udp.name()) == std::string("udp:") + target);
  const uint8_t a[] = {1, 2, 3}, b[] = {4, 5};
  REQUIRE(udp.write(a, sizeof a).bytes == 3);
  REQUIRE(udp.write(b, sizeof b).bytes == 2);
  uint8_t got[16];
  sockaddr_in from{};
  socklen_t fromLen = sizeof from;
  CHECK(::recvfrom(peer, got, sizeof got, 0, reinterpret_cast<sockaddr*>(&from), &fromLen) == 3);
  CHECK(::recv(peer, got, sizeof got, 0) == 2);  // a second datagram, not merged
  const uint8_t reply[] = {9, 8, 7, 6};
  REQUIRE(::sendto(peer, reply, sizeof reply, 0, reinterpret_cast<sockaddr*>(&from), fromLen) == 4);
  const IoResult r = udp.read(got, sizeof got, 1000);
  CHECK(r.status == IoStatus::Ok);
  REQUIRE(r.bytes == 4);
  CHECK(got[3] == 6);
  peerSocket.close();
  // Nobody listening any more: writes are lost as on a network, never an error or a block.
  for (int i = 0; i < 3; ++i) CHECK(udp.write(a, sizeof a).status == IoStatus::Ok);
  CHECK(udp.read(got, sizeof got, 0).status == IoStatus::Ok);

  UdpSocket bad;
  CHECK_FALSE(bad.open("127.0.0.1"));
  CHECK(std::string(bad.error()) == "udp:127.0.0.1: expected HOST:PORT");
}

TEST_CASE("a key file that is a FIFO is refused at once, in one line (issue 56, 2)") {
  cuetrack::test::TempDir tmp;
  const std::string fifo = tmp / "key";
  REQUIRE(::mkfifo(fifo.c_str(), 0600) == 0);
  auto reading = std::async(std::launch::async, [&] {
    uint8_t key[32];
    char err[512] = "";
    const bool ok = readKeyFile(fifo.c_str(), key, sizeof key, err, sizeof err);
    return std::make_pair(ok, std::string(err));
  });
  // Bounded: a reader that blocks in open() is released by opening the write end, so the
  // old behaviour fails here rather than hanging the test.
  const bool answered = reading.wait_for(std::chrono::seconds(5)) == std::future_status::ready;
  if (!answered) {
    const int w = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);
    if (w >= 0) ::close(w);
  }
  CHECK(answered);
  const auto [ok, err] = reading.get();
  CHECK_FALSE(ok);
  CHECK(err == fifo + ": not a regular file");
}

TEST_CASE("an all-zero or repeated-byte key is refused; a real one is read") {
  cuetrack::test::TempDir tmp;
  const std::string path = tmp / "key";
  auto tryKey = [&](const std::string& bytes, std::string* err) {
    FILE* f = std::fopen(path.c_str(), "wb");
    REQUIRE(f != nullptr);
    REQUIRE(std::fwrite(bytes.data(), 1, bytes.size(), f) == bytes.size());
    std::fclose(f);
    REQUIRE(::chmod(path.c_str(), 0600) == 0);
    uint8_t key[32];
    char e[512] = "";
    const bool ok = readKeyFile(path.c_str(), key, sizeof key, e, sizeof e);
    *err = e;
    return ok;
  };
  std::string err;
  CHECK_FALSE(tryKey(std::string(32, '\0'), &err));
  CHECK(err == path +
                   ": the key is one byte (0x00) repeated: not a secret; make one with head -c 32 "
                   "/dev/urandom");
  CHECK_FALSE(tryKey(std::string(32, 'A'), &err));
  CHECK(err.find("(0x41) repeated") != std::string::npos);
  std::string good(32, 'A');
  good[31] = 'B';
  CHECK(tryKey(good, &err));
}
