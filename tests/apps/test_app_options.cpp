// cuetrack's command line.
#include <catch2/catch.hpp>

#include <string>

#include "Options.hpp"

using namespace cuetrack::app;

namespace {
ParseResult parse(std::initializer_list<const char*> args, AppOptions* o, std::string* err) {
  static char storage[32][64];
  static char* argv[33];
  int argc = 0;
  argv[argc++] = const_cast<char*>("cuetrack");
  REQUIRE(args.size() < 32);
  for (const char* a : args) {
    std::snprintf(storage[argc], sizeof storage[0], "%s", a);
    argv[argc] = storage[argc];
    ++argc;
  }
  char buf[256] = "";
  const ParseResult r = parseOptions(argc, argv, o, buf, sizeof buf);
  *err = buf;
  return r;
}
}  // namespace

TEST_CASE("defaults: best preset, synthetic-or-Kinect source, ground truth on") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({}, &o, &err) == ParseResult::Run);
  CHECK(o.source == nullptr);
  CHECK(std::string(o.preset) == "best");
  CHECK(o.useGroundTruth);
  CHECK(o.frames == -1);
  CHECK(o.baud == 115200);
  CHECK_FALSE(o.realtime);
}

TEST_CASE("every option is read") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({"--source", "synth:occlusion", "--box",    "1,2.5,30,40", "--no-gt",
                 "--serial", "/dev/ttyS1",      "--baud",   "9600",        "--out",
                 "x.csv",    "--stdout",        "--frames", "12",          "--config",
                 "2.1",      "--seed",          "99",       "--quiet",     "--realtime"},
                &o, &err) == ParseResult::Run);
  CHECK(std::string(o.source) == "synth:occlusion");
  CHECK(o.hasBox);
  CHECK(o.box.y == 2.5f);
  CHECK(o.box.h == 40.f);
  CHECK_FALSE(o.useGroundTruth);
  CHECK(std::string(o.serialPath) == "/dev/ttyS1");
  CHECK(o.baud == 9600);
  CHECK(std::string(o.outPath) == "x.csv");
  CHECK(o.forceStdout);
  CHECK(o.frames == 12);
  CHECK(std::string(o.preset) == "2.1");
  CHECK(o.seed == 99);
  CHECK(o.quiet);
  CHECK(o.realtime);
}

TEST_CASE("--wait-camera goes with a Kinect source only") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({"--source", "kinect:colour", "--wait-camera"}, &o, &err) == ParseResult::Run);
  CHECK(o.waitCamera);
  REQUIRE(parse({"--source", "kinect"}, &o, &err) == ParseResult::Run);
  CHECK_FALSE(o.waitCamera);
  // A file or a scene that is missing stays missing; the default may be a scene.
  CHECK(parse({"--wait-camera"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--wait-camera needs --source kinect or kinect:colour");
  CHECK(parse({"--source", "rec1", "--wait-camera"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--wait-camera needs --source kinect or kinect:colour");
  CHECK(parse({"--wait-camera", "--source", "synth:moving"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--wait-camera needs --source kinect or kinect:colour");
  CHECK(parse({"--source", "kinect_lab_rec", "--wait-camera"}, &o, &err) == ParseResult::Error);
}

TEST_CASE("bad command lines give one line naming the option") {
  AppOptions o;
  std::string err;
  CHECK(parse({"--box", "1,2,0,4"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--box 1,2,0,4") == 0);
  CHECK(parse({"--box", "1,2,3"}, &o, &err) == ParseResult::Error);
  CHECK(parse({"--frames", "-3"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--frames -3") == 0);
  CHECK(parse({"--serial"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--serial needs a value") == 0);
  CHECK(parse({"--baud", "fast"}, &o, &err) == ParseResult::Error);
  CHECK(parse({"--seed", "x"}, &o, &err) == ParseResult::Error);
  CHECK(parse({"--what"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("unknown option '--what'") == 0);
  CHECK(parse({"--help"}, &o, &err) == ParseResult::Help);
  CHECK(std::string(usageText()).find("exit codes") != std::string::npos);
  // 0 frames would run nothing and report success, as bench and synth refuse.
  CHECK(parse({"--frames", "0"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--frames 0: expected a count >= 1");
  CHECK(parse({"--frames", "1"}, &o, &err) == ParseResult::Run);
}

TEST_CASE("an option given twice is an error, not 'the last one wins'") {
  AppOptions o;
  std::string err;
  CHECK(parse({"--box", "1,2,30,40", "--frames", "5", "--box", "5,6,30,40"}, &o, &err) ==
        ParseResult::Error);
  CHECK(err == "--box given twice");
  CHECK(parse({"--quiet", "--quiet"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--quiet given twice");
  // Two different --mavlink-* ids are two options.
  CHECK(parse({"--protocol", "mavlink", "--serial", "/dev/null", "--mavlink-sysid", "2",
               "--mavlink-compid", "3"},
              &o, &err) == ParseResult::Run);
  CHECK(parse({"--mavlink-sysid", "2", "--mavlink-sysid", "3"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--mavlink-sysid given twice");
}

TEST_CASE("--skip-bad-frames is off unless given") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({"--frames", "3"}, &o, &err) == ParseResult::Run);
  CHECK_FALSE(o.skipBadFrames);
  REQUIRE(parse({"--skip-bad-frames"}, &o, &err) == ParseResult::Run);
  CHECK(o.skipBadFrames);
}

TEST_CASE("--source kinect:MODE takes both or colour; depth alone is refused, naming it") {
  AppOptions o;
  std::string err;
  CHECK(parse({"--source", "kinect:colour"}, &o, &err) == ParseResult::Run);
  CHECK(std::string(o.source) == "kinect:colour");
  CHECK(parse({"--source", "kinect:both"}, &o, &err) == ParseResult::Run);
  CHECK(parse({"--source", "kinect"}, &o, &err) == ParseResult::Run);
  for (const char* bad : {"kinect:depth", "kinect:", "kinect:color2"}) {
    AppOptions b;
    CHECK(parse({"--source", bad}, &b, &err) == ParseResult::Error);
    CHECK(err.find(std::string("--source ") + bad + ":") == 0);
    CHECK(err.find("needs colour") != std::string::npos);
  }
}

TEST_CASE("--box: non-finite and absurd values are refused at parsing, sane ones kept") {
  AppOptions o;
  std::string err;
  // Plain decimals only, as for --frames: hex, exponents and blanks are refused.
  for (const char* box :
       {"1,1,inf,20", "1,1,1e30,1e30", "nan,1,10,10", "1,-inf,10,10", "1,1,10,nan",
        "200000,1,10,10", "1,1,100001,10", "0x123,1,10,10", "1,1,1e2,10", "1, 1,10,10", "1,,10,10",
        "1,1,10,10,", "-,1,10,10", "1.,.5,10,10x"}) {
    INFO(box);
    CHECK(parse({"--box", box}, &o, &err) == ParseResult::Error);
    CHECK(err.find(std::string("--box ") + box + ": expected X,Y,W,H") == 0);
  }
  REQUIRE(parse({"--box", "-5,-6,100000,7.5"}, &o, &err) == ParseResult::Run);
  CHECK(o.box.x == -5.f);
  CHECK(o.box.w == 100000.f);
  REQUIRE(parse({"--box", "1.,.5,+10,10"}, &o, &err) == ParseResult::Run);
  CHECK(o.box.y == 0.5f);
}

TEST_CASE("--seed takes plain digits only; --baud says unsupported for a number it cannot use") {
  AppOptions o;
  std::string err;
  CHECK(parse({"--seed", "-1"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--seed -1: expected a non-negative integer") == 0);
  CHECK(parse({"--seed", " 5"}, &o, &err) == ParseResult::Error);
  CHECK(parse({"--seed", "+5"}, &o, &err) == ParseResult::Error);
  CHECK(parse({"--seed", "0x10"}, &o, &err) == ParseResult::Error);
  for (const char* frames : {"0x10", "1e3", " 5", "5 "}) {
    INFO(frames);
    CHECK(parse({"--frames", frames}, &o, &err) == ParseResult::Error);
  }
  CHECK(parse({"--seed", "99999999999999999999999"}, &o, &err) == ParseResult::Error);
  REQUIRE(parse({"--seed", "18446744073709551615"}, &o, &err) == ParseResult::Run);
  CHECK(o.seed == 18446744073709551615ull);
  for (const char* baud : {"0", "-9600", "4000001"}) {
    INFO(baud);
    CHECK(parse({"--baud", baud}, &o, &err) == ParseResult::Error);
    CHECK(err.find(std::string("--baud ") + baud + ": unsupported") == 0);
  }
  CHECK(parse({"--baud", "fast"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--baud fast: not a number") == 0);
}

TEST_CASE("--protocol mavlink and its settings; each refused alone or out of range, named") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({"--serial", "/dev/ttyS0"}, &o, &err) == ParseResult::Run);
  CHECK(o.protocol == Protocol::Cuetrack);
  CHECK(o.mavSysId == 1);
  CHECK(o.mavCompId == 100);
  REQUIRE(parse({"--serial", "/dev/ttyS0", "--protocol", "mavlink", "--mavlink-sysid", "7",
                 "--mavlink-compid", "101", "--mavlink-mount", "0,-90,12.5", "--mavlink-offset",
                 "0.1,0,-0.05", "--mavlink-landing", "angles"},
                &o, &err) == ParseResult::Run);
  CHECK_FALSE(o.landingPosition);
  CHECK(o.mavlinkRateBytesPerS == 0);  // the link's default
  CHECK(o.protocol == Protocol::Mavlink);
  CHECK(o.mavSysId == 7);
  CHECK(o.mavCompId == 101);
  CHECK(o.mountDeg[1] == -90.f);
  CHECK(o.mountDeg[2] == 12.5f);
  CHECK(o.mountOffsetM[0] == Approx(0.1f));
  CHECK(o.mountOffsetM[2] == Approx(-0.05f));
  REQUIRE(parse({"--protocol", "mavlink", "--mavlink-udp", "127.0.0.1:14550"}, &o, &err) ==
          ParseResult::Run);
  CHECK(std::string(o.mavlinkUdp) == "127.0.0.1:14550");
  REQUIRE(parse({"--protocol", "mavlink", "--mavlink-udp", "127.0.0.1:14550", "--mavlink-rate",
                 "20000"},
                &o, &err) == ParseResult::Run);
  CHECK(o.mavlinkRateBytesPerS == 20000);
  REQUIRE(parse({"--serial", "x", "--protocol", "mavlink", "--mavlink-key", "k.bin"}, &o, &err) ==
          ParseResult::Run);
  CHECK(std::string(o.mavlinkKey) == "k.bin");
  CHECK(o.acceptSysIdCount == 0);  // from any system
  REQUIRE(parse({"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "1,255"}, &o,
                &err) == ParseResult::Run);
  CHECK(o.mavlinkKey == nullptr);  // unsigned unless a key is given
  REQUIRE(o.acceptSysIdCount == 2);
  CHECK(o.acceptSysIds[0] == 1);
  CHECK(o.acceptSysIds[1] == 255);
  const struct {
    std::initializer_list<const char*> args;
    const char* says;
  } bad[] = {
      {{"--protocol", "mavlink"}, "--protocol mavlink needs --serial DEV or --mavlink-udp"},
      {{"--protocol", "mavlink", "--mavlink-udp", "localhost"},
       "--mavlink-udp localhost: expected"},
      {{"--protocol", "mavlink", "--mavlink-udp", "h:70000"}, "--mavlink-udp h:70000: expected"},
      {{"--protocol", "mavlink", "--mavlink-udp", "h:1", "--serial", "x"},
       "--serial and --mavlink-udp: one link at a time"},
      {{"--mavlink-udp", "h:1"}, "--mavlink-udp needs --protocol mavlink"},
      {{"--serial", "x", "--protocol", "mavlink2"}, "--protocol mavlink2: expected"},
      {{"--serial", "x", "--mavlink-sysid", "3"}, "--mavlink-sysid needs --protocol mavlink"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-compid", "0"}, "--mavlink-compid 0:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-sysid", "256"},
       "--mavlink-sysid 256:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-mount", "0,90"},
       "--mavlink-mount 0,90: expected ROLL,PITCH,YAW"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-mount", "0,nan,0"},
       "--mavlink-mount 0,nan,0:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-offset", "1,2,3x"},
       "--mavlink-offset 1,2,3x:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-landing", "ned"},
       "--mavlink-landing ned: expected frd or angles"},
      {{"--serial", "x", "--mavlink-landing", "angles"}, "--mavlink-landing needs --protocol"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-rate", "10"},
       "--mavlink-rate 10: expected bytes a second"},
      {{"--serial", "x", "--mavlink-rate", "5000"}, "--mavlink-rate needs --protocol"},
      {{"--serial", "x", "--mavlink-accept-sysid", "1"}, "--mavlink-accept-sysid needs --protocol"},
      {{"--serial", "x", "--mavlink-key", "k"}, "--mavlink-key needs --protocol"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "0"},
       "--mavlink-accept-sysid 0: expected system ids 1..255"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "1,,2"},
       "--mavlink-accept-sysid 1,,2:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "0x10"},
       "--mavlink-accept-sysid 0x10:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "1,2,3,4,5,6,7,8,9"},
       "--mavlink-accept-sysid 1,2,3,4,5,6,7,8,9:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "1,"},
       "--mavlink-accept-sysid 1,:"},
      // Plain decimals in every number (the command-line layer's checks, apps/common).
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-mount", "0x1,0,0"},
       "--mavlink-mount 0x1,0,0: expected ROLL,PITCH,YAW"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-offset", "0,1e1,0"},
       "--mavlink-offset 0,1e1,0:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-sysid", "0x10"},
       "--mavlink-sysid 0x10:"},
      {{"--serial", "x", "--protocol", "mavlink", "--mavlink-accept-sysid", "1", "--mavlink-key",
        "k", "--mavlink-accept-sysid=2"},
       "--mavlink-accept-sysid given twice"},
  };
  for (const auto& b : bad) {
    INFO(b.says);
    CHECK(parse(b.args, &o, &err) == ParseResult::Error);
    CHECK(err.find(b.says) == 0);
  }
}

TEST_CASE(
    "--show, --select, --snapshot and --video are read; combinations that cannot be are "
    "refused in one line") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({}, &o, &err) == ParseResult::Run);
  CHECK_FALSE(o.show);
  CHECK_FALSE(o.select);
  CHECK(o.snapshotPath == nullptr);
  CHECK(o.videoPath == nullptr);
  REQUIRE(parse({"--show", "--select", "--video", "run.avi"}, &o, &err) == ParseResult::Run);
  CHECK(o.show);
  CHECK(o.select);
  CHECK(std::string(o.videoPath) == "run.avi");
  REQUIRE(parse({"--snapshot", "f.png"}, &o, &err) == ParseResult::Run);
  CHECK(std::string(o.snapshotPath) == "f.png");

  CHECK(parse({"--select", "--box", "1,2,3,4"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--select and --box: one target at a time");
  CHECK(parse({"--snapshot", "f.png", "--show"}, &o, &err) == ParseResult::Error);
  CHECK(err.rfind("--snapshot saves a frame and exits", 0) == 0);
  CHECK(parse({"--snapshot"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--snapshot needs a value (see --help)");
  CHECK(parse({"--video"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--video needs a value (see --help)");
}

TEST_CASE("--opt=value is the same as --opt value (issue 42: --box=1,2,3,4 was refused)") {
  AppOptions o;
  std::string err;
  REQUIRE(parse({"--box=1,2,3,4", "--frames=7", "--source=synth:moving"}, &o, &err) ==
          ParseResult::Run);
  CHECK(o.hasBox);
  CHECK(o.box.x == 1.f);
  CHECK(o.box.h == 4.f);
  CHECK(o.frames == 7);
  CHECK(std::string(o.source) == "synth:moving");
  REQUIRE(parse({"--box", "1,2,3,4"}, &o, &err) == ParseResult::Run);
  CHECK(o.box.w == 3.f);
  CHECK(parse({"--box=1,2,3,4", "--box", "1,2,3,4"}, &o, &err) == ParseResult::Error);
  CHECK(err == "--box given twice");
  CHECK(parse({"--box=1,2,0,4"}, &o, &err) == ParseResult::Error);
  CHECK(err.find("--box 1,2,0,4: expected X,Y,W,H") == 0);
  // The --mavlink-* option named without --protocol mavlink is the first one given.
  CHECK(parse({"--serial", "x", "--mavlink-landing", "angles", "--mavlink-sysid", "3"}, &o, &err) ==
        ParseResult::Error);
  CHECK(err == "--mavlink-landing needs --protocol mavlink");
}
