// The tools' one command-line layer (apps/common, on CLI11): both spellings of an option
// with a value, a repeated option refused, one line naming the bad option and exit code
// 2, --help generated from the declarations; and the shared value checks.
#include <catch2/catch.hpp>
#include <string>
#include <vector>

#include "TestPaths.hpp"
#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"

using namespace cuetrack;

namespace {

struct Parsed {
  int rc = -1;
  long frames = 7;
  std::string scene = "moving";
  bool hash = false;
  Box box{};
  std::vector<std::string> inputs, sends;
};

Parsed parse(std::vector<const char*> args, cli::Quotes q = cli::Quotes::Value) {
  Parsed p;
  cli::Command cmd("tool", "A tool.", "exit codes: 0 done, 2 bad command line", q);
  cmd.number("--frames", "N", "frames", 1, 1000, &p.frames);
  cmd.text("--scene", "NAME", "scene", &p.scene);
  cmd.flag("--hash", "hash", &p.hash);
  cmd.option("--box", "X,Y,W,H", "box", [&p](const std::string& v) { return cli::box(v, &p.box); });
  cmd.list("--send", "CMD", "sends", &p.sends);
  cmd.positionals("INPUT", "inputs", &p.inputs);
  args.insert(args.begin(), "tool");
  p.rc = cmd.parse(static_cast<int>(args.size()), args.data());
  return p;
}

}  // namespace

TEST_CASE("--opt value and --opt=value are the same option") {
  Parsed a = parse({"--frames", "12", "--scene", "box", "--box", "1,2,3,4", "a", "b"});
  Parsed b = parse({"--frames=12", "--scene=box", "--box=1,2,3,4", "a", "b"});
  for (const Parsed* p : {&a, &b}) {
    CHECK(p->rc == -1);
    CHECK(p->frames == 12);
    CHECK(p->scene == "box");
    CHECK(p->box.x == 1.f);
    CHECK(p->box.h == 4.f);
    CHECK(p->inputs == std::vector<std::string>{"a", "b"});
  }
  const Parsed none = parse({});
  CHECK(none.rc == -1);
  CHECK(none.frames == 7);  // defaults stay
  CHECK_FALSE(none.hash);
}

TEST_CASE("a repeatable option takes one value each time") {
  const Parsed p = parse({"--send", "a", "in1", "--send=b", "--send", "c", "in2"});
  CHECK(p.rc == -1);
  CHECK(p.sends == std::vector<std::string>{"a", "b", "c"});
  CHECK(p.inputs == std::vector<std::string>{"in1", "in2"});
  CHECK(parse({"--send"}).rc == cli::kExitUsage);
}

TEST_CASE("a bad command line is exit code 2") {
  CHECK(parse({"--frames", "12", "--frames", "13"}).rc == cli::kExitUsage);  // given twice
  CHECK(parse({"--frames=12", "--frames", "12"}).rc == cli::kExitUsage);
  CHECK(parse({"--hash", "--hash"}).rc == cli::kExitUsage);  // a switch too
  CHECK(parse({"--bogus"}).rc == cli::kExitUsage);
  CHECK(parse({"-x"}).rc == cli::kExitUsage);
  CHECK(parse({"--frames"}).rc == cli::kExitUsage);  // no value
  CHECK(parse({"--frames", "0"}).rc == cli::kExitUsage);
  CHECK(parse({"--frames", "abc"}).rc == cli::kExitUsage);
  CHECK(parse({"--box", "1,1,inf,20"}).rc == cli::kExitUsage);
  // Numbers are plain decimals (CLI11's own parsing would take 0x10, 0b1, 1e2).
  for (const char* bad : {"0x10", "0o7", "0b1", "1e2", " 5", "+5"}) {
    INFO(bad);
    CHECK(parse({"--frames", bad}).rc == cli::kExitUsage);
  }
  CHECK(parse({"--box", "0x1,1,10,10"}).rc == cli::kExitUsage);
  CHECK(parse({"--hash", "--frames", "5"}).rc == -1);
}

TEST_CASE("the error line names the option, the value and what was expected") {
  cli::Command quoted("tool", "", "", cli::Quotes::Value);
  CHECK(quoted.badValue("--frames", "abc", "expected N") == "--frames 'abc': expected N");
  cli::Command plain("tool", "", "", cli::Quotes::None);
  CHECK(plain.badValue("--frames", "0", "expected N") == "--frames 0: expected N");
  // A newline in a value does not split the line.
  CHECK(plain.badValue("--scene", "a\nb", "unknown") == "--scene a?b: unknown");
}

TEST_CASE("--help is generated from the declarations and ends with the exit codes") {
  cli::Command cmd("tool", "A tool.", "exit codes: 0 done, 2 bad command line");
  long n = 0;
  cmd.number("--frames", "N", "frames to run", 1, 10, &n);
  const std::string help = cmd.help();
  CHECK(help.find("A tool.") != std::string::npos);
  CHECK(help.find("--frames N") != std::string::npos);
  CHECK(help.find("frames to run") != std::string::npos);
  CHECK(help.find("exit codes: 0 done") != std::string::npos);
}

TEST_CASE("whole numbers: decimal digits only, within range") {
  long v = -5;
  CHECK(cli::wholeNumber("0", 0, 10, &v).empty());
  CHECK(v == 0);
  CHECK(cli::wholeNumber("-3", -5, 10, &v).empty());
  CHECK(v == -3);
  for (const char* bad :
       {"", " 5", "+5", "5 ", "0x10", "1e3", "1.5", "11", "-6", "abc", "99999999999999999999999"}) {
    INFO(bad);
    CHECK(cli::wholeNumber(bad, -5, 10, &v) == "expected a whole number in -5..10");
  }
  double d = 0;
  CHECK(cli::decimal("-2.5", -27, 27, &d).empty());
  CHECK(d == -2.5);
  for (const char* good : {".5", "1.", "+2", "-0"}) {
    INFO(good);
    CHECK(cli::decimal(good, -27, 27, &d).empty());
  }
  // Plain decimals only: strtod would also read blanks, hex, exponents, inf and nan.
  for (const char* bad : {"", "28", "1x", "nan", "inf", "-27.5", "0x10", "0x1p3", "1e1", " 5", "5 ",
                          "-", ".", "1.2.3"}) {
    INFO(bad);
    CHECK_FALSE(cli::decimal(bad, -27, 27, &d).empty());
  }
  uint64_t s = 0;
  CHECK(cli::seed("18446744073709551615", &s).empty());
  CHECK(s == 18446744073709551615ull);
  CHECK_FALSE(cli::seed("-1", &s).empty());
  CHECK_FALSE(cli::seed("18446744073709551616", &s).empty());
  CHECK_FALSE(cli::seed("", &s).empty());
}

TEST_CASE("boxes, sizes, baud rates, HOST:PORT, choices") {
  Box b{};
  CHECK(cli::box("10.5,20,30,40", &b).empty());
  CHECK(b.x == 10.5f);
  for (const char* bad : {"1,1,inf,20", "nan,1,10,10", "1,1,1e30,1e30", "1,2,3", "1,2,3,4,5",
                          "1,2,0,4", "1,2,3,-4", "1;2;3;4", "0x123,1,10,10", "1,1,1e2,10",
                          "1, 1,10,10", "1,,10,10", "1,1,10,10,", "-,1,10,10"}) {
    INFO(bad);
    CHECK_FALSE(cli::box(bad, &b).empty());
  }
  CHECK(cli::box("1.,.5,+10,10", &b).empty());
  CHECK(b.y == 0.5f);
  float three[3];
  CHECK(cli::numbers("-90,0.5,+1", 3, 360.f, three).empty());
  CHECK_FALSE(cli::numbers("0x10,0,0", 3, 360.f, three).empty());
  CHECK_FALSE(cli::numbers("0,1e2,0", 3, 360.f, three).empty());
  int w = 0, h = 0;
  CHECK(cli::imageSize("320x240", 8, 640, 480, &w, &h).empty());
  CHECK((w == 320 && h == 240));
  CHECK_FALSE(cli::imageSize("640x481", 8, 640, 480, &w, &h).empty());
  CHECK_FALSE(cli::imageSize("7x8", 8, 640, 480, &w, &h).empty());
  CHECK_FALSE(cli::imageSize("320", 8, 640, 480, &w, &h).empty());
  int baud = 0;
  CHECK(cli::baudRate("921600", &baud).empty());
  CHECK(baud == 921600);
  CHECK(cli::baudRate("300", &baud) == "unsupported (9600..921600)");
  CHECK(cli::baudRate("fast", &baud) == "not a number");
  CHECK(cli::hostPort("127.0.0.1:14550").empty());
  CHECK(cli::hostPort("[::1]:14550").empty());
  CHECK_FALSE(cli::hostPort("127.0.0.1").empty());
  CHECK_FALSE(cli::hostPort("host:0").empty());
  int k = -1;
  CHECK(cli::oneOf("depth", "rgb|depth|gray", &k).empty());
  CHECK(k == 1);
  CHECK(cli::oneOf("dep", "rgb|depth|gray", &k) == "expected one of rgb,depth,gray");
  CHECK(cli::existingFile(CUETRACK_SOURCE_DIR "/README.md").empty());
  CHECK_FALSE(cli::existingFile(CUETRACK_SOURCE_DIR).empty());
  CHECK_FALSE(cli::existingFile("/nonexistent/file").empty());
}
