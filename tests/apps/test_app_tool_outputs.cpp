// The one output guard of every tool (apps/common OutputGuard), end to end with the real
// binaries: each output option of each tool, pointed at its own input (the video, its
// ground truth, a folder read, through a symlink too) and at another output, is refused
// with exit 2 and one line on stderr, before anything is written: the inputs keep their
// bytes, --force or not. (cuetrack-trackspeed and cuetrack-microbench write only stdout.)
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdlib>
#include <initializer_list>
#include <string>
#include <vector>

#include "Process.hpp"
#include "TempDir.hpp"

using namespace cuetrack::test;

namespace {

constexpr int kTimeoutMs = 60000;

// The bytes of a file ("" when absent: compared, so a removed input shows).
std::string bytes(const std::string& path) {
  std::string out;
  if (FILE* f = std::fopen(path.c_str(), "rb")) {
    char buf[65536];
    size_t n = 0;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) out.append(buf, n);
    std::fclose(f);
  }
  return out;
}

struct Fixture {
  TempDir dir;
  std::string video = dir / "vid.avi", gt = dir / "vid.gt.txt", rec = dir / "rec";
  std::string videoBytes, gtBytes, recIndex;

  Fixture() {
    const char* synthAvi[] = {CUETRACK_SYNTH_BIN, "--scene", "occlusion", "--frames",    "4",
                              "--format",         "avi",     "--out",     video.c_str(), nullptr};
    REQUIRE(runToEnd(synthAvi, "/dev/null", nullptr, kTimeoutMs) == 0);
    const char* synthRec[] = {CUETRACK_SYNTH_BIN, "--scene", "moving", "--frames", "3", "--out",
                              rec.c_str(),        nullptr};
    REQUIRE(runToEnd(synthRec, "/dev/null", nullptr, kTimeoutMs) == 0);
    REQUIRE(::symlink(video.c_str(), (dir / "link.avi").c_str()) == 0);
    videoBytes = bytes(video);
    gtBytes = bytes(gt);
    recIndex = bytes(rec + "/INDEX.txt");
    REQUIRE(!videoBytes.empty());
    REQUIRE(!gtBytes.empty());
    REQUIRE(!recIndex.empty());
  }

  // Runs the tool; it must refuse with exit 2 and one line naming the clash, and leave
  // every input as it was.
  void refused(std::initializer_list<std::string> args) {
    std::vector<const char*> argv;
    std::string shown;
    for (const std::string& a : args) {
      argv.push_back(a.c_str());
      shown += a + " ";
    }
    argv.push_back(nullptr);
    const std::string err = dir / "err.txt";
    INFO(shown);
    CHECK(runToEnd(argv.data(), "/dev/null", err.c_str(), kTimeoutMs) == 2);
    const std::vector<std::string> said = lines(slurp(err));
    INFO(slurp(err));
    REQUIRE(said.size() == 1);
    CHECK((said[0].find("may not overwrite an input") != std::string::npos ||
           said[0].find("one would overwrite the other") != std::string::npos));
    CHECK(bytes(video) == videoBytes);
    CHECK(bytes(gt) == gtBytes);
    CHECK(bytes(rec + "/INDEX.txt") == recIndex);
  }
};

}  // namespace

TEST_CASE("no tool writes over its input or one output over another", "[apps][outputs]") {
  Fixture f;
  const std::string& v = f.video;
  const std::string& g = f.gt;
  const std::string& r = f.rec;
  const std::string link = f.dir / "link.avi", other = f.dir / "other";

  // Each option once against each kind of input (one spawn costs ~0.2 s of CPU).
  SECTION("cuetrack: --out, --video, --snapshot") {
    f.refused({CUETRACK_APP_BIN, "--source", v, "--out", v});
    f.refused({CUETRACK_APP_BIN, "--source", v, "--video", g});
    f.refused({CUETRACK_APP_BIN, "--source", v, "--snapshot", link});
    f.refused({CUETRACK_APP_BIN, "--source", r, "--out", r + "/INDEX.txt"});
    f.refused({CUETRACK_APP_BIN, "--source", r, "--gt", g, "--video", g});
    f.refused({CUETRACK_APP_BIN, "--source", v, "--out", other, "--video", other});
    f.refused({CUETRACK_APP_BIN, "--source", v, "--out", other, "--snapshot", other});
  }

#ifdef CUETRACK_BENCH_BIN
  SECTION("cuetrack-bench: files and folders") {
    f.refused({CUETRACK_BENCH_BIN, v, "--json", v});
    f.refused({CUETRACK_BENCH_BIN, v, "--markdown", g});
    f.refused({CUETRACK_BENCH_BIN, "--gt", g, r, "--json", g});
    for (const char* opt :
         {"--csv", "--plots", "--results", "--overlay", "--video", "--peer-cache"})
      f.refused({CUETRACK_BENCH_BIN, r, opt, r + "/sub"});
    f.refused({CUETRACK_BENCH_BIN, v, "--video", f.dir.path()});  // DIR/vid.avi is the input
    f.refused({CUETRACK_BENCH_BIN, v, "--json", other, "--markdown", other});
    f.refused({CUETRACK_BENCH_BIN, v, "--csv", f.dir.path(), "--json", f.dir / "vid.overlap.csv"});
    f.refused(
        {CUETRACK_BENCH_BIN, v, "--plots", f.dir.path(), "--markdown", f.dir / "success.png"});
  }
#endif

  SECTION("cuetrack-convert and cuetrack-synth: --out, --force or not") {
    f.refused({CUETRACK_CONVERT_BIN, v, "--format", "avi", "--out", v, "--force"});
    f.refused({CUETRACK_CONVERT_BIN, v, "--format", "avi", "--out", link, "--force"});
    f.refused({CUETRACK_CONVERT_BIN, r, "--gt", g, "--format", "avi", "--out", v, "--force"});
    f.refused({CUETRACK_CONVERT_BIN, r, "--out", r + "/out"});
    f.refused({CUETRACK_SYNTH_BIN, "--scene", "rand:1:" + r, "--out", r + "/out"});
  }

  SECTION("cuetrack-listen: --csv, --state") {
    f.refused({CUETRACK_LISTEN_BIN, v, "--csv", v});
    f.refused({CUETRACK_LISTEN_BIN, v, "--state", link});
    f.refused({CUETRACK_LISTEN_BIN, "/dev/null", "--csv", other, "--state", other});
  }

#ifdef CUETRACK_RECORD_BIN
  SECTION("cuetrack-record: --out inside the recording it replays") {
    ::setenv("FAKENECT_PATH", r.c_str(), 1);
    f.refused({CUETRACK_RECORD_BIN, "--out", r + "/again"});
    f.refused({CUETRACK_RECORD_BIN, "--out", r});
    ::unsetenv("FAKENECT_PATH");
  }
#endif
}
