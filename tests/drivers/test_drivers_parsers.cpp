// Memory-buffer parsers: PNM headers, INDEX names, ground-truth lines, intrinsics.
#include <catch2/catch.hpp>

#include <cstring>
#include <string>
#include <vector>

#include "cuetrack/drivers/GroundTruth.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

using namespace cuetrack;
using namespace cuetrack::rec;

namespace {
std::vector<uint8_t> bytes(const std::string& s) {
  return std::vector<uint8_t>(s.begin(), s.end());
}
}  // namespace

TEST_CASE("PNM header: comments, sizes, truncation", "[parsers]") {
  char err[128] = "";
  PnmHeader h;
  std::string img = "P6\n# comment\n2 1\n255\n" + std::string(6, 'x');
  auto b = bytes(img);
  REQUIRE(parsePnmHeader(b.data(), b.size(), &h, err, sizeof err));
  CHECK(h.type == '6');
  CHECK(h.width == 2);
  CHECK(h.height == 1);
  CHECK(h.dataOffset == img.size() - 6);
  Rgb8 px[2];
  REQUIRE(decodePnmRgb(b.data(), b.size(), h, px, err, sizeof err));
  CHECK(px[1].b == 'x');

  b.pop_back();
  CHECK_FALSE(parsePnmHeader(b.data(), b.size(), &h, err, sizeof err));
  CHECK(std::string(err).find("truncated") != std::string::npos);
  auto big = bytes("P5 641 480 255\n");
  CHECK_FALSE(parsePnmHeader(big.data(), big.size(), &h, err, sizeof err));
  auto bad = bytes("P3 1 1 255\n1 2 3");
  CHECK_FALSE(parsePnmHeader(bad.data(), bad.size(), &h, err, sizeof err));
  auto noMax = bytes("P5 1 1");
  CHECK_FALSE(parsePnmHeader(noMax.data(), noMax.size(), &h, err, sizeof err));
}

TEST_CASE("16-bit PGM in both byte orders", "[parsers]") {
  char err[128] = "";
  auto b = bytes(std::string("P5 2 1 65535\n") + std::string("\x01\x02\x03\x04", 4));
  PnmHeader h;
  REQUIRE(parsePnmHeader(b.data(), b.size(), &h, err, sizeof err));
  uint16_t d[2];
  REQUIRE(decodePnm16(b.data(), b.size(), h, Endian::Little, d, err, sizeof err));
  CHECK(d[0] == 0x0201);
  REQUIRE(decodePnm16(b.data(), b.size(), h, Endian::Big, d, err, sizeof err));
  CHECK(d[0] == 0x0102);
  auto eight = bytes("P5 2 1 255\nab");
  REQUIRE(parsePnmHeader(eight.data(), eight.size(), &h, err, sizeof err));
  CHECK_FALSE(decodePnm16(eight.data(), eight.size(), h, Endian::Little, d, err, sizeof err));
}

TEST_CASE("fakenect INDEX names", "[parsers]") {
  char err[160] = "";
  IndexEntry e;
  const std::string ok = "d-1294192326.785372-2170375364.pgm\r";
  REQUIRE(parseIndexLine(ok.data(), ok.size() - 1, &e, err, sizeof err));
  CHECK(e.kind == 'd');
  CHECK(e.seconds == Approx(1294192326.785372));
  CHECK(e.timestamp == 2170375364u);
  for (const char* bad : {"q-1.0-2.ppm", "r-1.0-2.pgm", "r-x-2.ppm", "r-1.0-.ppm",
                          "r-1.0-99999999999.ppm", "r-1.0-2.ppm/../x", "", "a-1-2.dump.x"}) {
    INFO(bad);
    CHECK_FALSE(parseIndexLine(bad, std::strlen(bad), &e, err, sizeof err));
  }
}

TEST_CASE("fakenect INDEX seconds out of range are refused", "[parsers]") {
  char err[160] = "";
  IndexEntry e;
  for (const char* bad : {"r-1e300-0.ppm", "r-10000000001.0-0.ppm", "r--1.0-0.ppm"}) {
    INFO(bad);
    CHECK_FALSE(parseIndexLine(bad, std::strlen(bad), &e, err, sizeof err));
  }
  const std::string huge = "r-1e300-0.ppm";
  CHECK_FALSE(parseIndexLine(huge.data(), huge.size(), &e, err, sizeof err));
  CHECK(std::string(err).find("seconds 1e+300 outside 0..10000000000") != std::string::npos);
  const std::string ok = "r-9999999999.5-0.ppm";
  CHECK(parseIndexLine(ok.data(), ok.size(), &e, err, sizeof err));
}

TEST_CASE("ground truth lines: BoBoT and OTB", "[parsers][gt]") {
  char err[200] = "";
  GroundTruth gt;
  const std::string bobot = "./Vid_C_juice.avi\r\n0 0.5 0.25 0.1 0.2\r\n1 0 0 0 0\r\n\r\n";
  REQUIRE(gt.parse(bobot.data(), bobot.size(), "g.txt", GtFormat::Bobot, err, sizeof err));
  CHECK(gt.header() == "./Vid_C_juice.avi");
  REQUIRE(gt.count() == 2);
  Box b;
  REQUIRE(gt.boxAt(0, 320, 240, &b));
  CHECK(b.x == Approx(160));
  CHECK(b.y == Approx(60));
  CHECK(b.w == Approx(32));
  CHECK(b.h == Approx(48));
  REQUIRE(gt.boxAt(1, 320, 240, &b));
  CHECK(b.empty());
  CHECK_FALSE(gt.boxAt(2, 320, 240, &b));

  const std::string gap = "hdr\n0 0.1 0.1 0.1 0.1\n2 0.1 0.1 0.1 0.1\n";
  CHECK_FALSE(gt.parse(gap.data(), gap.size(), "g.txt", GtFormat::Bobot, err, sizeof err));
  CHECK(std::string(err).find("g.txt:3: frame index 2, expected 1") != std::string::npos);

  const std::string otb = "10,20,30,40\n11\t21\t31\t41\n12, 22, 32, 42\n";
  REQUIRE(gt.parse(otb.data(), otb.size(), "o.txt", GtFormat::Otb, err, sizeof err));
  REQUIRE(gt.count() == 3);
  REQUIRE(gt.boxAt(0, 640, 480, &b));
  CHECK(b.x == Approx(9));  // 1-based -> 0-based
  CHECK(b.w == Approx(30));
  const std::string otbBad = "10,20,30,40\n10,20,30\n";
  CHECK_FALSE(gt.parse(otbBad.data(), otbBad.size(), "o.txt", GtFormat::Otb, err, sizeof err));
  CHECK(std::string(err).find("o.txt:2:") != std::string::npos);
  const std::string nan = "nan,1,2,3\n";
  CHECK_FALSE(gt.parse(nan.data(), nan.size(), "o.txt", GtFormat::Otb, err, sizeof err));
}

TEST_CASE("too few numbers on a line: the count, not a garbled character", "[parsers][gt]") {
  char err[200] = "";
  GroundTruth gt;
  const std::string bobot = "hdr\n0 0.1 0.1 0.1 0.1\n1 0.1 0.2 0.3\n";
  CHECK_FALSE(gt.parse(bobot.data(), bobot.size(), "g.txt", GtFormat::Bobot, err, sizeof err));
  CHECK(std::string(err) == "g.txt:3: expected 4 numbers, found 3");
  const std::string otb = "1,2,3\n";
  CHECK_FALSE(gt.parse(otb.data(), otb.size(), "o.txt", GtFormat::Otb, err, sizeof err));
  CHECK(std::string(err) == "o.txt:1: expected 4 numbers, found 3");
  const std::string ctl = "1,2\x01,3,4\n";
  CHECK_FALSE(gt.parse(ctl.data(), ctl.size(), "o.txt", GtFormat::Otb, err, sizeof err));
  CHECK(std::string(err) == "o.txt:1: unexpected byte 0x01 after number 2");
  CameraIntrinsics k;
  const std::string three = "518 519 325.5\n";
  CHECK_FALSE(parseIntrinsics(three.data(), three.size(), &k, err, sizeof err));
  CHECK(std::string(err) == "expected 4 numbers, found 3");
}

TEST_CASE("intrinsics.txt", "[parsers]") {
  char err[128] = "";
  CameraIntrinsics k;
  const std::string ok = "# fx fy cx cy\n518.0 519.0 325.5 253.5\n";
  REQUIRE(parseIntrinsics(ok.data(), ok.size(), &k, err, sizeof err));
  CHECK(k.fx == Approx(518.0));
  CHECK(k.cy == Approx(253.5));
  const std::string bad = "518 519 325\n";
  CHECK_FALSE(parseIntrinsics(bad.data(), bad.size(), &k, err, sizeof err));
  const std::string zero = "0 519 325 253\n";
  CHECK_FALSE(parseIntrinsics(zero.data(), zero.size(), &k, err, sizeof err));
}

TEST_CASE("intrinsics.txt: implausible focal lengths and principal points", "[parsers]") {
  char err[128] = "";
  CameraIntrinsics k;
  const std::string tiny = "1e-30 1e-30 325.5 253.5\n";
  CHECK_FALSE(parseIntrinsics(tiny.data(), tiny.size(), &k, err, sizeof err));
  CHECK(std::string(err) == "fx 1e-30 outside 10..100000 px");
  const std::string huge = "518 1e6 325.5 253.5\n";
  CHECK_FALSE(parseIntrinsics(huge.data(), huge.size(), &k, err, sizeof err));
  CHECK(std::string(err).find("fy 1e+06 outside") == 0);
  const std::string cxOut = "518 519 -5000 253.5\n";
  CHECK_FALSE(parseIntrinsics(cxOut.data(), cxOut.size(), &k, err, sizeof err));
  CHECK(std::string(err).find("principal point -5000,253.5 outside") == 0);
  const std::string cyOut = "518 519 325 481\n";
  CHECK_FALSE(parseIntrinsics(cyOut.data(), cyOut.size(), &k, err, sizeof err));
  const std::string edge = "10 100000 0 480\n";
  CHECK(parseIntrinsics(edge.data(), edge.size(), &k, err, sizeof err));
}

TEST_CASE("frame counts of a spec's :frames suffix", "[parsers]") {
  int n = 0;
  CHECK(rec::parseFrameCount("1", &n));
  CHECK(n == 1);
  CHECK(rec::parseFrameCount("1000000", &n));
  CHECK(n == 1000000);
  n = 7;
  for (const char* bad : {"", "0", "-3", "1000001", "12x", "x", " ", "1.5"}) {
    INFO("'" << bad << "'");
    CHECK_FALSE(rec::parseFrameCount(bad, &n));
    CHECK(n == 7);  // untouched on failure
  }
}
