// cuetrack-listen's command line: one line for every bad one, commands checked up front.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "ListenOptions.hpp"

using namespace cuetrack::listen;

namespace {
ListenParse parse(std::vector<const char*> args, ListenOptions* o, std::string* err) {
  args.insert(args.begin(), "cuetrack-listen");
  char buf[512] = "";
  const ListenParse r = parseListenOptions(static_cast<int>(args.size()),
                                           const_cast<char**>(args.data()), o, buf, sizeof buf);
  *err = buf;
  return r;
}
}  // namespace

TEST_CASE("listen options: a port, values, repeatable --send") {
  static ListenOptions o;
  std::string err;
  REQUIRE(parse({"/dev/ttyUSB0", "--baud", "921600", "--send", "reset", "--send", "start:1,2,30,40",
                 "--tracks", "5", "--reconnect", "--state", "s.txt"},
                &o, &err) == ListenParse::Run);
  CHECK(std::string(o.portPath) == "/dev/ttyUSB0");
  CHECK(o.baud == 921600);
  CHECK(o.numSends == 2);
  CHECK(o.commands[0].type == CTP_CMD_RESET);
  CHECK(o.commands[1].type == CTP_CMD_START);
  CHECK(o.commands[1].id == 2);
  CHECK(o.maxTracks == 5);
  CHECK(o.reconnect);
  CHECK(std::string(o.statePath) == "s.txt");
}

TEST_CASE("listen options: bad command lines are one line each") {
  static ListenOptions o;
  std::string err;
  CHECK(parse({}, &o, &err) == ListenParse::Error);
  CHECK(err == "missing PORT (see --help)");
  CHECK(parse({"p", "--baud", "300"}, &o, &err) == ListenParse::Error);
  CHECK(err == "--baud 300: unsupported (9600..921600)");
  CHECK(parse({"p", "--tracks", "0"}, &o, &err) == ListenParse::Error);
  CHECK(err == "--tracks 0: expected a count >= 1");
  CHECK(parse({"p", "--csv", "a", "--csv", "b"}, &o, &err) == ListenParse::Error);
  CHECK(err == "--csv given twice");
  CHECK(parse({"p", "q"}, &o, &err) == ListenParse::Error);
  CHECK(err == "unexpected argument 'q' (one PORT only)");
  CHECK(parse({"p", "--send", "jump"}, &o, &err) == ListenParse::Error);
  CHECK(err.find("jump") != std::string::npos);
  CHECK(parse({"p", "--help"}, &o, &err) == ListenParse::Help);
}
