// What the tools say when something is wrong names the true cause and the next step, with
// the exit code --help documents (issue 55): a folder's missing ground truth by the file
// its reader looks for, a recording cut short mid-way (the summary so far and
// --skip-bad-frames), a stray NAME.txt beside a video when --box gives the target (a
// warning, not a failed run), an unknown scene (exit 2 in every tool), a bench sequence
// without ground truth (no table of dashes), --quiet's losses, and cuetrack's --gt and
// --no-gt.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

#include "Process.hpp"
#include "TempDir.hpp"

using namespace cuetrack::test;

namespace {

constexpr int kTimeoutMs = 120000;

struct Ran {
  int code;
  std::string out, err;
};

Ran run(const TempDir& dir, std::vector<std::string> args) {
  std::vector<const char*> argv;
  for (const std::string& a : args) argv.push_back(a.c_str());
  argv.push_back(nullptr);
  const std::string out = dir / "out.txt", err = dir / "err.txt";
  Ran r{runToEnd(argv.data(), out.c_str(), err.c_str(), kTimeoutMs), "", ""};
  r.out = slurp(out);
  r.err = slurp(err);
  return r;
}

// A whole file's bytes (slurp stops at 1 MiB; a video is larger).
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

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("each message names the cause and the next step, with the documented code",
          "[apps][messages]") {
  TempDir dir;
  const std::string video = dir / "vid.avi", gt = dir / "vid.gt.txt";
  REQUIRE(run(dir, {CUETRACK_SYNTH_BIN, "--scene", "occlusion", "--frames", "40", "--format", "avi",
                    "--out", video})
              .code == 0);

  SECTION("--gt names the ground truth; --no-gt scores none") {
    const std::string renamed = dir / "truth.txt";
    REQUIRE(::rename(gt.c_str(), renamed.c_str()) == 0);
    Ran r = run(dir, {CUETRACK_APP_BIN, "--source", video, "--gt", renamed, "--frames", "5"});
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(has(r.err, "ground truth (" + renamed + ")"));
    CHECK(has(r.err, "ground-truth mean overlap"));
    REQUIRE(::rename(renamed.c_str(), gt.c_str()) == 0);
    r = run(dir, {CUETRACK_APP_BIN, "--source", video, "--no-gt", "--box", "200,150,60,60",
                  "--frames", "5"});
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK_FALSE(has(r.err, "ground-truth mean overlap"));
    r = run(dir, {CUETRACK_APP_BIN, "--source", "synth:moving", "--gt", gt});
    CHECK(r.code == 2);
    CHECK(has(r.err, "--gt: synth:moving has no ground-truth file"));
  }

  SECTION("a folder without ground truth names the file its reader looks for") {
    const std::string otb = dir / "otb";
    REQUIRE(run(dir, {CUETRACK_CONVERT_BIN, video, "--format", "otb", "--out", otb}).code == 0);
    REQUIRE(::unlink((otb + "/groundtruth_rect.txt").c_str()) == 0);
    const Ran r = run(dir, {CUETRACK_APP_BIN, "--source", otb});
    INFO(r.err);
    CHECK(r.code == 2);
    CHECK(has(r.err, otb + "/groundtruth_rect.txt"));
  }

  SECTION("a recording cut short: the summary so far, and --skip-bad-frames") {
    const std::string cut = dir / "cut.avi";
    const std::string whole = bytes(video);
    writeText(cut, whole.substr(0, whole.size() / 2));
    writeText(dir / "cut.gt.txt", slurp(gt));
    const Ran r = run(dir, {CUETRACK_APP_BIN, "--source", cut});
    INFO(r.err);
    CHECK(r.code == 1);
    CHECK(has(r.err, "cuetrack: summary: "));
    CHECK(has(r.err, "--skip-bad-frames skips its bad frames"));
  }

  SECTION("a stray NAME.txt beside the video with --box: a warning, the run goes on") {
    const std::string other = dir / "notes.avi";
    writeText(other, bytes(video));
    writeText(dir / "notes.txt", "things to try tomorrow\n");
    const Ran r =
        run(dir, {CUETRACK_APP_BIN, "--source", other, "--box", "200,150,60,60", "--frames", "5"});
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(has(r.err, "notes.txt"));
    CHECK(has(r.err, "not used as ground truth (no score)"));
  }

  SECTION("--quiet still reports the frames the target was not tracked on") {
    const Ran r = run(dir, {CUETRACK_APP_BIN, "--source", "synth:occlusion", "--quiet"});
    INFO(r.err);
    CHECK(r.code == 0);
    CHECK(has(r.err, "cuetrack: target not tracked on "));
  }

  SECTION("an unknown scene is a bad command line in every tool") {
    for (const char* tool : {CUETRACK_APP_BIN, CUETRACK_CONVERT_BIN}) {
      const Ran r = run(dir, {tool, tool == std::string(CUETRACK_APP_BIN) ? "--source" : "--bench",
                              "synth:nosuch"});
      INFO(tool << ": " << r.err);
      CHECK(r.code == 2);
      CHECK(has(r.err, "synth:nosuch: unknown scene 'nosuch' (scenes: moving"));
    }
#ifdef CUETRACK_BENCH_BIN
    const Ran r = run(dir, {CUETRACK_BENCH_BIN, "synth:nosuch"});
    CHECK(r.code == 2);
    CHECK(has(r.err, "synth:nosuch: unknown scene"));
#endif
  }

#ifdef CUETRACK_BENCH_BIN
  SECTION("cuetrack-bench without ground truth: the reason, no table of dashes") {
    const std::string bare = dir / "bare.avi";
    writeText(bare, bytes(video));
    const Ran r = run(dir, {CUETRACK_BENCH_BIN, bare, "--runs", "1", "--quiet"});
    INFO(r.out << r.err);
    CHECK(r.code == 1);
    CHECK_FALSE(has(r.out, "Overlap and hit rate"));
    CHECK(has(r.out, "Not run:"));
    CHECK(has(r.err, "no ground-truth box to initialise from (a video's NAME.gt.txt"));
  }
#endif
}
