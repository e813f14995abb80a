// No output of cuetrack destroys an input or another output, and no run that wrote or
// read nothing ends as a success (the real binary, host build with OpenCV):
//   - --out / --video over the source (a recording's INDEX.txt or frame, a folder, a
//     video, a video's ground truth, through a symlink or a hard link), or --out and
//     --video on one file: exit 2, one line naming both paths, the input unchanged;
//   - --video on a full disk (a .avi that is /dev/full): exit 3, the read-back says so;
//   - a video with no decodable frame: exit 1 naming it.
#include <catch2/catch.hpp>

#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "Process.hpp"
#include "TempDir.hpp"
#include "TestPrograms.hpp"

using namespace cuetrack::test;

namespace {

constexpr int kTimeoutMs = 120000;  // generous: 2 cores shared by many builds

int run(std::vector<const char*> argv, const std::string& err) {
  argv.push_back(nullptr);
  const int status = runToEnd(argv.data(), "/dev/null", err.c_str(), kTimeoutMs);
  REQUIRE(status != kRunNotStarted);
  return status;
}

void synth(const std::string& out, const char* format) {
  TempDir logs;
  REQUIRE(run({CUETRACK_SYNTH_BIN, "--scene", "moving", "--frames", "4", "--format", format,
               "--out", out.c_str()},
              logs / "err") == 0);
}

}  // namespace

TEST_CASE("an output over an input, or over another output, is refused naming both") {
  TempDir tmp;
  const std::string rec = tmp / "rec", avi = tmp / "v.avi", err = tmp / "err";
  synth(rec, "fakenect");
  synth(avi, "avi");
  const std::string index = readText(rec + "/INDEX.txt"), video = readText(avi);
  const std::string frame = rec + "/" + lines(index).at(0).substr(0, lines(index).at(0).find(' '));
  REQUIRE(::symlink(avi.c_str(), (tmp / "link.avi").c_str()) == 0);
  REQUIRE(::link((rec + "/INDEX.txt").c_str(), (tmp / "hard.csv").c_str()) == 0);
  const std::string hard = tmp / "hard.csv", link = tmp / "link.avi";
  const std::string both = tmp / "s.avi", index2 = rec + "/INDEX.txt", newCsv = rec + "/new.csv";
  const std::string gt = tmp / "v.gt.txt";
  const struct {
    std::vector<const char*> args;
    std::string says;
  } cases[] = {
      {{"--source", rec.c_str(), "--out", index2.c_str()},
       "--out " + index2 + " is inside --source " + rec},
      {{"--source", rec.c_str(), "--out", frame.c_str()}, "--out " + frame + " is inside"},
      {{"--source", rec.c_str(), "--out", newCsv.c_str()}, "--out " + newCsv + " is inside"},
      {{"--source", rec.c_str(), "--out", hard.c_str()}, "--out " + hard + " is inside"},
      {{"--source", avi.c_str(), "--video", avi.c_str()},
       "--video " + avi + " is the same file as --source " + avi},
      {{"--source", avi.c_str(), "--video", link.c_str()},
       "--video " + link + " is the same file as --source " + avi},
      {{"--source", avi.c_str(), "--out", gt.c_str()},
       "is the same file as --source's ground truth"},
      {{"--out", both.c_str(), "--video", both.c_str()},
       "--out " + both + " and --video " + both + " are the same file"},
  };
  for (const auto& c : cases) {
    std::vector<const char*> argv = {CUETRACK_APP_BIN, "--frames", "2"};
    argv.insert(argv.end(), c.args.begin(), c.args.end());
    INFO(c.says);
    CHECK(run(argv, err) == 2);
    const std::vector<std::string> said = lines(readText(err));
    REQUIRE(said.size() == 1);
    CHECK(said[0].find(c.says) != std::string::npos);
  }
  // Nothing was touched, nothing was made.
  CHECK(readText(rec + "/INDEX.txt") == index);
  CHECK(readText(avi) == video);
  CHECK(::access(newCsv.c_str(), F_OK) != 0);
  CHECK(::access(both.c_str(), F_OK) != 0);
  // Two outputs to a device destroy no file: allowed.
  CHECK(run({CUETRACK_APP_BIN, "--frames", "2", "--quiet", "--out", "/dev/null"}, err) == 0);
}

TEST_CASE("--video on a full disk fails at close: exit 3, the read-back says so") {
  TempDir tmp;
  const std::string full = tmp / "full.avi", err = tmp / "err";
  REQUIRE(::symlink("/dev/full", full.c_str()) == 0);  // every write: ENOSPC, unreported
  CHECK(run({CUETRACK_APP_BIN, "--frames", "5", "--quiet", "--video", full.c_str()}, err) == 3);
  const std::string said = readText(err);
  CHECK(said.find("--video " + full + ": only 0 of 5 frames written could be read back") !=
        std::string::npos);
  CHECK(said.find("wrote ") == std::string::npos);
  // Control: a disk with room reads back whole.
  const std::string ok = tmp / "ok.avi";
  CHECK(run({CUETRACK_APP_BIN, "--frames", "5", "--video", ok.c_str()}, err) == 0);
  CHECK(readText(err).find("wrote " + ok + ": 5 frames") != std::string::npos);
}

TEST_CASE("a video with no decodable frame is exit 1 naming it, not an empty success") {
  TempDir tmp;
  const std::string avi = tmp / "none.avi", err = tmp / "err";
  synth(avi, "avi");
  // The container says it has no frame (AVI header and stream lengths 0), and the frames it
  // still holds are blank.
  std::string data = readText(avi);
  for (size_t at = data.find("00dc", data.find("movi")); at != std::string::npos;
       at = data.find("00dc", at + 8)) {
    uint32_t size = 0;
    std::memcpy(&size, data.data() + at + 4, 4);
    if (at + 8 + size > data.size()) break;
    data.replace(at + 8, size, std::string(size, '\0'));
  }
  for (const char* chunk : {"avih", "strh"}) {
    const size_t at = data.find(chunk);
    REQUIRE(at != std::string::npos);
    const size_t field = at + 8 + (std::string(chunk) == "avih" ? 16 : 32);
    data.replace(field, 4, std::string(4, '\0'));
  }
  writeText(avi, data);
  REQUIRE(std::remove((tmp / "none.gt.txt").c_str()) == 0);  // nothing says how many to expect
  CHECK(run({CUETRACK_APP_BIN, "--source", avi.c_str(), "--box", "1,1,20,20", "--quiet"}, err) ==
        1);
  CHECK(readText(err) == "cuetrack: " + avi + ": no decodable frame (it is empty)\n");
}
