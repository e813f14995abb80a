// cuetrack-bench as a user runs it: bad command lines, missing and broken sequences
// (clear error, the next sequence still runs, non-zero exit), trackers that cannot run,
// outputs that cannot be written (exit 1 each).
#include <sys/wait.h>

#include <catch2/catch.hpp>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "SharedData.hpp"
#include "Skip.hpp"

namespace {

struct Run {
  int exitCode = -1;
  std::string out;  // stdout and stderr together
};

// stdoutTo: where the bench's stdout goes ("": with stderr into Run::out).
Run runBench(const std::string& args, const std::string& stdoutTo = "") {
  Run r;
  const std::string cmd = std::string(CUETRACK_BENCH_EXE) + " " + args + " 2>&1" +
                          (stdoutTo.empty() ? "" : " >" + stdoutTo);
  FILE* p = popen(cmd.c_str(), "r");
  REQUIRE(p);
  char buf[4096];
  size_t n;
  while ((n = std::fread(buf, 1, sizeof buf, p)) > 0) r.out.append(buf, n);
  const int status = pclose(p);
  r.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string readAll(const std::string& path) {
  std::ifstream in(path);
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

}  // namespace

TEST_CASE("a bad command line exits 2 with one clear line pointing to --help") {
  Run r = runBench("--runs zero synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out == "cuetrack-bench: --runs: 'zero' is not a positive whole number (see --help)\n");
  r = runBench("--tracker '' synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--tracker '': an empty tracker name") != std::string::npos);
  r = runBench("--tracker cuetrack,, synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--tracker 'cuetrack,,': an empty tracker name") != std::string::npos);
  r = runBench("--config best,,2.1 synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("an empty configuration name") != std::string::npos);
  r = runBench("--help");
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("exit codes: 0 ") != std::string::npos);
  CHECK(r.out.find("2 bad command line") != std::string::npos);
  r = runBench("--tracker opencv-goturn synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("unknown tracker 'opencv-goturn'") != std::string::npos);
  r = runBench("--config 3.1 synth:moving");
  CHECK(r.exitCode == 2);
  r = runBench("--config best-nothing synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("unknown configuration 'best-nothing'") != std::string::npos);
  r = runBench("--stride 0 synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--stride: '0' is not a whole number from 1 to 1000") != std::string::npos);
  r = runBench("--drop-frames 99 synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--drop-frames: '99' is not a whole percentage from 0 to 95") !=
        std::string::npos);
  r = runBench("");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("no sequence given") != std::string::npos);
  r = runBench("synth:moving --reverse");  // --from / --to / --reverse precede a sequence
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--from / --to / --reverse are not followed by a sequence") !=
        std::string::npos);
  r = runBench("--from 9 --to 3 synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--to 3 lies before --from 9 (for synth:moving)") != std::string::npos);
  r = runBench("--from -1 synth:moving");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("--from: '-1' is not a frame index") != std::string::npos);
}

#if CUETRACK_BENCH_TEST_SYNTH
TEST_CASE("a missing sequence is reported, the next one runs, the exit code says so") {
  const std::string json = "bench_cli_missing.json";
  const Run r = runBench(
      "/nonexistent/Vid_X.avi synth:moving --frames 8 --runs 1 --quiet "
      "--tracker cuetrack,opencv-mosse --config best --json " +
      json);
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("/nonexistent/Vid_X.avi") != std::string::npos);
  CHECK(r.out.find("(skipped)") != std::string::npos);
  const nlohmann::json v = nlohmann::json::parse(readAll(json));
  REQUIRE(v.is_array());
  REQUIRE(v.size() == 2);
  const nlohmann::json& cue = v[0];
  CHECK(cue["tracker"] == "cuetrack");
  const nlohmann::json& seqs = cue["sequences"];
  REQUIRE(seqs.size() == 2);
  CHECK(seqs[0]["overlap"].is_null());
  CHECK(seqs[1]["name"] == "moving");
  CHECK(seqs[1]["frames"] == 7);  // 8 frames, the first initialises
  REQUIRE(seqs[1]["overlap"].is_number());
  CHECK(seqs[1]["overlap"].get<double>() > 30.0);
  CHECK(seqs[1]["allocs"].get<double>() == 0.0);  // the core does not allocate while tracking
}
#endif

#if CUETRACK_BENCH_TEST_SYNTH
TEST_CASE("ablations of best (a beyond-the-paper switch off) run as configurations") {
  Run r = runBench("synth:moving --frames 6 --runs 1 --quiet --config best-nolost,best-fixedsize");
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("best-nolost") != std::string::npos);
  CHECK(r.out.find("best-fixeds") != std::string::npos);
  r = runBench("synth:moving --frames 9 --runs 1 --quiet --stride 2 --config best-nofastmotion");
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("best-nofastm") != std::string::npos);
  CHECK(r.out.find("4 frames left out") != std::string::npos);
  // A removed switch is refused with the list of those there are.
  r = runBench("synth:moving --frames 6 --runs 1 --quiet --config best-nomodeguard");
  CHECK(r.exitCode == 2);
  CHECK(r.out.find("unknown configuration 'best-nomodeguard'") != std::string::npos);
}

TEST_CASE("3D presets place a synthetic target's centre within centimetres; 2D ones report none") {
  // The scene's cylinder has an 80 mm radius: reporting its front surface, or a centre
  // half a diameter off, would be 80 mm out in depth.
  const std::string json = "bench_cli_centre_mm.json";
  const Run r =
      runBench("synth:moving --frames 60 --runs 2 --quiet --config best,2.1,2.4 --json " + json);
  CHECK(r.exitCode == 0);
  CHECK(r.out.find("3D centre error") != std::string::npos);
  const nlohmann::json v = nlohmann::json::parse(readAll(json));
  REQUIRE(v.size() == 3);
  for (size_t i = 0; i < 2; ++i) {
    const nlohmann::json& s = v[i]["sequences"][0];
    INFO(v[i]["config"].get<std::string>());
    REQUIRE(s["center_mm"].is_number());
    CHECK(s["center_mm"].get<double>() < 30.0);
    CHECK(s["center_z_mm"].get<double>() < 15.0);
  }
  CHECK(v[2]["config"] == "2.4");
  CHECK(v[2]["sequences"][0]["center_mm"].is_null());
  std::remove(json.c_str());
}

TEST_CASE("--rgb-only drops depth: best falls back to 2D, 2.1 cannot start (a finding)") {
  const char* kNoDepth = "cannot run: init failed: no depth";
  Run r = runBench("synth:moving --frames 6 --runs 1 --quiet --config best,2.1");
  CHECK(r.exitCode == 0);
  CHECK(r.out.find(kNoDepth) == std::string::npos);  // control: the scene has depth
  r = runBench("synth:moving --frames 6 --runs 1 --quiet --rgb-only --config best,2.1");
  CHECK(r.exitCode == 0);
  CHECK(r.out.find(kNoDepth) != std::string::npos);
  const size_t row = r.out.find("\ncuetrack best ");  // best's row of the first table
  REQUIRE(row != std::string::npos);
  const std::string line = r.out.substr(row + 1, r.out.find('\n', row + 1) - row - 1);
  CHECK(line.find("cannot run") == std::string::npos);
}

TEST_CASE("lost results exit 1: stdout full, --results not writable") {
  Run r = runBench("synth:moving:5 --runs 1 --quiet", "/dev/full");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("cuetrack-bench: stdout: cannot write the report") != std::string::npos);
  r = runBench("synth:moving:5 --runs 2 --quiet --results /proc/cuetrack-nope");
  CHECK(r.exitCode == 1);
  const size_t at = r.out.find("/proc/cuetrack-nope");
  REQUIRE(at != std::string::npos);
  CHECK(r.out.find("/proc/cuetrack-nope", at + 1) == std::string::npos);  // said once
  r = runBench("synth:moving:5 --runs 1 --quiet");
  CHECK(r.exitCode == 0);  // control
}
#endif

#if CUETRACK_BENCH_TEST_SYNTH
TEST_CASE("--from / --to / --reverse apply to the next sequence; an empty slice fails it alone") {
  const Run r = runBench(
      "--from 50 synth:moving --to 4 --reverse synth:moving synth:moving --frames 8 --runs 1 "
      "--quiet --tracker opencv-mosse");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("cuetrack-bench: moving: no frame has an index in 50..end (of 8 frames) "
                   "(skipped)") != std::string::npos);
  // The two others ran, each under its own name.
  CHECK(r.out.find("moving.to4.rev") != std::string::npos);
  CHECK(r.out.find("failed") != std::string::npos);
}
#endif

#if CUETRACK_BENCH_TEST_READERS && defined(CUETRACK_SYNTH_EXE)
TEST_CASE("sequences without a usable start or with frames changing size exit 1, each named") {
  const std::string synth = std::string(CUETRACK_SYNTH_EXE) + " --scene moving --frames 6 ";
  const std::string make =
      "rm -rf bench_cli_seq && mkdir bench_cli_seq && cd bench_cli_seq && " + synth +
      "--format otb --out otb >/dev/null && rm otb/groundtruth_rect.txt && " + synth +
      "--out gt >/dev/null && sed -i '2s/.*/0 -0.5 0.5 0.05 0.1/' gt/groundtruth.txt && " + synth +
      "--out sz >/dev/null && " + synth +
      "--size 320x240 --out small >/dev/null && for p in r d; do "
      "f=$(grep \"^$p-\" sz/INDEX.txt | sed -n 4p) && cp small/$f sz/$f || exit 1; done";
  REQUIRE(std::system(make.c_str()) == 0);
  Run r = runBench("bench_cli_seq/otb --runs 1 --quiet");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("cuetrack best on otb: no ground-truth box") != std::string::npos);
  r = runBench("bench_cli_seq/gt --runs 1 --quiet");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("cuetrack best on gt: frame 0: ground-truth box -320,240,32,48 lies outside") !=
        std::string::npos);
  r = runBench("bench_cli_seq/sz --runs 1 --quiet");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("sz") != std::string::npos);
  CHECK(r.out.find("320x240") != std::string::npos);
}
#endif

#if CUETRACK_BENCH_TEST_READERS
TEST_CASE("a broken video gets one line naming it") {
  {
    std::ofstream f("bench_cli_broken.avi");
    f << "not a video at all";
  }
  {
    std::ofstream f("bench_cli_broken.gt.txt");
    f << "./bench_cli_broken.avi\r\n0 0.1 0.1 0.2 0.2\r\n";
  }
  const Run r = runBench("bench_cli_broken.avi --runs 1 --quiet --tracker opencv-mosse");
  CHECK(r.exitCode == 1);
  CHECK(r.out.find("bench_cli_broken") != std::string::npos);
}

TEST_CASE("RGB-D configurations on RGB-only BoBoT video are reported as unable to run") {
  const std::string video = cuetrack::test::sharedDataDir() + "/bobot/Vid_C_juice.avi";
  if (!std::ifstream(video)) CUETRACK_SKIP("shared data absent (" << video << ")");
  const Run r = runBench(video + " --frames 6 --runs 1 --quiet --config 2.1,1.1");
  CHECK(r.exitCode == 0);  // a finding, not a broken sequence
  CHECK(r.out.find("cuetrack 2.1 on Vid_C_juice: cannot run") != std::string::npos);
}
#endif
