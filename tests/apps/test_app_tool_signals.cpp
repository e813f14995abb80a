// Every tool installs its stop handlers first thing: SIGTERM at 0, 50 or 500 ms after the
// start ends it with its final line and the exit code its --help documents. At 0 ms the
// signal is sent while the child still has it blocked (inherited from this process), so
// it is pending from its first instruction: the tool must take it once its handlers are
// in, not die of it. Times are reached by polling the clock; the assertions are on what
// the tool printed and returned. (cuetrack-record needs a Kinect: not here.)
#include <catch2/catch.hpp>

#include <signal.h>

#include <chrono>
#include <string>
#include <vector>

#include "Process.hpp"
#include "TempDir.hpp"

using namespace cuetrack::test;

namespace {

constexpr int kExitTimeoutMs = 60000;

struct Expect {
  int code;
  const char* line;  // a line of stderr that must hold this text (the final line's)
};

// Starts argv with SIGTERM blocked, sends SIGTERM after delayMs, and checks the exit code
// and stderr.
void stopAt(int delayMs, const std::vector<std::string>& args, const Expect& want,
            const TempDir& dir) {
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  const std::string err = dir / "err.txt";
  INFO(args[0] << " stopped at " << delayMs << " ms");
  sigset_t term, old;
  sigemptyset(&term);
  sigaddset(&term, SIGTERM);
  REQUIRE(pthread_sigmask(SIG_BLOCK, &term, &old) == 0);
  ChildProcess child;
  const auto start = std::chrono::steady_clock::now();
  const bool started = child.start(argv.data(), "/dev/null", err.c_str());
  pthread_sigmask(SIG_SETMASK, &old, nullptr);
  REQUIRE(started);
  waitFor(
      [&] {
        return std::chrono::steady_clock::now() - start >= std::chrono::milliseconds(delayMs);
      },
      delayMs + 1000);
  child.signal(SIGTERM);
  int status = -1;
  REQUIRE(child.wait(kExitTimeoutMs, &status));
  const std::string said = slurp(err);
  INFO(said);
  CHECK(status == want.code);
  CHECK(said.find(want.line) != std::string::npos);
}

}  // namespace

TEST_CASE("a stop at 0, 50 or 500 ms ends every tool as its help says", "[apps][signals]") {
  TempDir dir;
  const std::string out = dir / "out";
  for (const int ms : {0, 50, 500}) {
    stopAt(ms, {CUETRACK_APP_BIN, "--source", "synth:moving", "--frames", "100000"},
           {0, "cuetrack: summary: "}, dir);
    stopAt(ms, {CUETRACK_LISTEN_BIN, dir / "no-port-yet", "--wait-port", "60"},
           {0, "cuetrack-listen: interrupted: 0 tracks"}, dir);
    stopAt(ms, {CUETRACK_SYNTH_BIN, "--scene", "moving", "--frames", "100000", "--out", out},
           {1, "interrupted; the partial output was removed"}, dir);
    CHECK(!fileExists(out.c_str()));
    stopAt(ms,
           {CUETRACK_CONVERT_BIN, "synth:moving:100000", "--format", "avi", "--out", out + ".avi"},
           {1, "interrupted; the partial output was removed"}, dir);
    CHECK(!fileExists((out + ".avi").c_str()));
    stopAt(ms, {CUETRACK_TRACKSPEED_BIN, "--frames", "1999", "--preset", "best"},
           {1, "cuetrack-trackspeed: interrupted"}, dir);
#ifdef CUETRACK_MICROBENCH_BIN
    stopAt(ms, {CUETRACK_MICROBENCH_BIN, "--runs", "10000"},
           {1, "cuetrack-microbench: interrupted"}, dir);
#endif
#ifdef CUETRACK_BENCH_BIN
    stopAt(ms, {CUETRACK_BENCH_BIN, "synth:moving", "--runs", "100", "--quiet"},
           {3, "figures so far, marked partial"}, dir);
#endif
  }
}
