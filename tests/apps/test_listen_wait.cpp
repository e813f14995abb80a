// cuetrack-listen --wait-port: a port that appears after the listener started (socat's
// pty, a USB adapter plugged in) is waited for; one that never comes fails after the wait.
// Every wait polls an observable condition with a bound; no sleep synchronises.
#include <catch2/catch.hpp>

#include <signal.h>

#include <string>

#include "Process.hpp"
#include "Skip.hpp"
#include "TestPrograms.hpp"

using namespace cuetrack::test;

namespace {
constexpr int kTimeoutMs = 120000;  // generous: 2 cores shared by many builds

}  // namespace

TEST_CASE("cuetrack-listen waits for a port that appears after it started") {
  if (!fileExists("/usr/bin/socat")) CUETRACK_SKIP("socat missing (scripts/setup.sh)");
  PtyPair pty;  // its folder exists, its links not yet
  const std::string out = std::string(pty.dir()) + "/listen.out";
  const std::string err = std::string(pty.dir()) + "/listen.err";
  const char* largv[] = {CUETRACK_LISTEN_BIN, pty.b(), "--tracks", "5",
                         "--wait-port",       "60",    nullptr};
  ChildProcess listen;
  REQUIRE(listen.start(largv, out.c_str(), err.c_str()));
  REQUIRE(
      waitFor([&] { return slurp(err).find("not there yet") != std::string::npos; }, kTimeoutMs));
  REQUIRE(pty.start());
  // 300 frames at 30 Hz: the listener opens its end long before the stream ends.
  const char* aargv[] = {CUETRACK_APP_BIN, "--serial", pty.a(),   "--realtime",
                         "--frames",       "300",      "--quiet", nullptr};
  ChildProcess app;
  REQUIRE(app.start(aargv, nullptr, nullptr));
  int status = -1;
  REQUIRE(listen.wait(kTimeoutMs, &status));
  CHECK(status == 0);
  CHECK(slurp(err).find("--tracks reached: 5 tracks") != std::string::npos);
  app.signal(SIGTERM);
  REQUIRE(app.wait(kTimeoutMs, &status));
  CHECK(status == 0);
}

TEST_CASE("cuetrack-listen gives up on a port that never comes, exit 1, naming it") {
  PtyPair pty;  // only for its private folder: never started
  const std::string path = std::string(pty.dir()) + "/never";
  const std::string err = std::string(pty.dir()) + "/listen.err";
  const char* argv[] = {CUETRACK_LISTEN_BIN, path.c_str(), "--wait-port", "1", nullptr};
  ChildProcess listen;
  REQUIRE(listen.start(argv, nullptr, err.c_str()));
  int status = -1;
  REQUIRE(listen.wait(kTimeoutMs, &status));
  CHECK(status == 1);  // the port cannot be opened (--help's exit codes)
  const std::string e = slurp(err);
  CHECK(e.find(path + ": cannot open") != std::string::npos);
  CHECK(e.find("waited 1 s") != std::string::npos);
}
