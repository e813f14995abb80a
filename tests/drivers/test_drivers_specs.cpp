// The pan:, still: and rand: source specs, parsed without OpenCV: good specs give the values the
// readers use; a bad one gives one line naming the spec and what is wrong with it.
#include <catch2/catch.hpp>

#include <string>

#include "cuetrack/drivers/StillSpecs.hpp"

using namespace cuetrack;
using namespace cuetrack::rec;

namespace {

// The error of a spec that must fail, checked to start with the spec and be one line.
std::string panError(const std::string& spec) {
  PanSpec p;
  char err[1024] = "";
  CHECK_FALSE(parsePanSpec(spec.c_str(), &p, err, sizeof err));
  const std::string e = err;
  CHECK(e.rfind(spec + ": ", 0) == 0);
  CHECK(e.find('\n') == std::string::npos);
  return e;
}

std::string stillError(const std::string& spec) {
  StillSpec s;
  char err[1024] = "";
  CHECK_FALSE(parseStillSpec(spec.c_str(), &s, err, sizeof err));
  const std::string e = err;
  CHECK(e.rfind(spec + ": ", 0) == 0);
  CHECK(e.find('\n') == std::string::npos);
  return e;
}

bool has(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("pan: spec, every field", "[specs]") {
  PanSpec p;
  char err[512] = "";
  REQUIRE(
      parsePanSpec("pan:nyu/rgb/a.png,nyu/depth/a.png,302,102,60,80,518.5,519,325.5,253.5,0.2:90",
                   &p, err, sizeof err));
  CHECK(p.rgbPath == "nyu/rgb/a.png");
  CHECK(p.depthPath == "nyu/depth/a.png");
  CHECK(p.box.x == 302.f);
  CHECK(p.box.y == 102.f);
  CHECK(p.box.w == 60.f);
  CHECK(p.box.h == 80.f);
  CHECK(p.intrinsics.fx == 518.5f);
  CHECK(p.intrinsics.fy == 519.f);
  CHECK(p.intrinsics.cx == 325.5f);
  CHECK(p.intrinsics.cy == 253.5f);
  CHECK(p.mmPerUnit == 0.2f);
  CHECK(p.frames == 90);
}

TEST_CASE("pan: spec, defaults and paths with ':'", "[specs]") {
  PanSpec p;
  char err[512] = "";
  REQUIRE(parsePanSpec("pan:c:1.png,d.png,1,2,3,4,500,500,320,240", &p, err, sizeof err));
  CHECK(p.rgbPath == "c:1.png");  // ':' before the last comma is part of a path
  CHECK(p.mmPerUnit == 1.f);
  CHECK(p.frames == kPanDefaultFrames);
  // The "pan:" prefix is optional (the reader is also handed the body alone).
  REQUIRE(parsePanSpec("c.png,d.png,1,2,3,4,500,500,320,240:1", &p, err, sizeof err));
  CHECK(p.frames == 1);
}

TEST_CASE("pan: spec, bad ones name what is wrong", "[specs]") {
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320"),
            "expected pan:RGB,DEPTH,x,y,w,h,fx,fy,cx,cy[,mmPerUnit][:frames] (9 fields)"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320,240,1,2"), "(12 fields)"));
  CHECK(has(panError("pan:c.png,d.png,1,2,wide,4,500,500,320,240"), "w 'wide' is not a number"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320,"), "cy '' is not a number"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320,240,nan"),
            "mmPerUnit 'nan' is not a number"));
  CHECK(has(panError("pan:c.png,d.png,1,2,0,4,500,500,320,240"),
            "w, h, fx, fy and mmPerUnit must be positive"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,-5,320,240"), "must be positive"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320,240:0"),
            "frame count '0' is not a number in 1..1000000"));
  CHECK(has(panError("pan:c.png,d.png,1,2,3,4,500,500,320,240:ten"), "frame count 'ten'"));
  CHECK(has(panError("pan:,d.png,1,2,3,4,500,500,320,240"), "colour (RGB) image's path is empty"));
  CHECK(has(panError("pan:c.png,,1,2,3,4,500,500,320,240"), "depth (DEPTH) image's path is empty"));
}

TEST_CASE("still: spec, every field", "[specs]") {
  StillSpec s;
  char err[512] = "";
  REQUIRE(
      parseStillSpec("still:tum/rgb/1.png,tum/depth/1.png,525,526,319.5,239.5,0.2:flat-turn@250,"
                     "170,40:60",
                     &s, err, sizeof err));
  CHECK(s.rgbPath == "tum/rgb/1.png");
  CHECK(s.depthPath == "tum/depth/1.png");
  CHECK(s.intrinsics.fx == 525.f);
  CHECK(s.intrinsics.fy == 526.f);
  CHECK(s.intrinsics.cx == 319.5f);
  CHECK(s.intrinsics.cy == 239.5f);
  CHECK(s.mmPerUnit == 0.2f);
  CHECK(s.scene == "flat-turn");
  CHECK(s.uPx == 250.f);
  CHECK(s.vPx == 170.f);
  CHECK(s.gapMm == 40.f);
  CHECK(s.frames == 60);
}

TEST_CASE("still: spec, defaults and paths with '@' and ':'", "[specs]") {
  StillSpec s;
  char err[512] = "";
  REQUIRE(
      parseStillSpec("still:a@b:c.png,d.png,500,500,320,240:moving@1,2,0", &s, err, sizeof err));
  CHECK(s.rgbPath == "a@b:c.png");  // parsed from the right
  CHECK(s.scene == "moving");
  CHECK(s.mmPerUnit == 1.f);
  CHECK(s.gapMm == 0.f);
  CHECK(s.frames == -1);  // the scene's own
}

TEST_CASE("still: spec, bad ones name what is wrong", "[specs]") {
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240"), "(no :SCENE@u,v,gapMm)"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240:moving@1,2"),
            "expected still:RGB,DEPTH,fx,fy,cx,cy[,mmPerUnit]:SCENE@u,v,gapMm[:frames] "
            "(6 still fields, 2 placement fields)"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320:moving@1,2,3"), "(5 still fields"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,y:moving@1,2,3"), "cy 'y' is not a number"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240:moving@1,v,3"), "v 'v' is not a number"));
  CHECK(has(stillError("still:c.png,d.png,0,500,320,240:moving@1,2,3"),
            "fx, fy and mmPerUnit must be positive"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240,-1:moving@1,2,3"), "must be positive"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240:moving@1,2,-3"),
            "gapMm must be >= 0 (the target in front)"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240:moving@1,2,3:0"), "frame count '0'"));
  CHECK(has(stillError("still:c.png,d.png,500,500,320,240:@1,2,3"), "scene's name"));
  CHECK(has(stillError("still:c.png,,500,500,320,240:moving@1,2,3"), "depth (DEPTH) image's path"));
}

TEST_CASE("still label: the dataset folder and the image's stem", "[specs]") {
  CHECK(stillLabel("nyu/rgb/joinmap-5.png") == "nyu-joinmap-5");
  CHECK(stillLabel("data/tum/color/1.png") == "tum-1");
  CHECK(stillLabel("stills/a.png") == "stills-a");
  CHECK(stillLabel("a.png") == "a");
}

TEST_CASE("rand: spec, the seed and the data folder", "[specs]") {
  RandomSpec r;
  char err[256] = "";
  REQUIRE(parseRandomSpec("rand:17", &r, err, sizeof err));
  CHECK(r.seed == 17);
  CHECK(r.dataDir.empty());
  REQUIRE(parseRandomSpec("rand:3:/data/with:colon", &r, err, sizeof err));
  CHECK(r.seed == 3);
  CHECK(r.dataDir == "/data/with:colon");
  for (const char* bad :
       {"rand:", "rand:x", "rand:-1", "rand:1.5", "rand:99999999999999999999", "rand:4:"}) {
    INFO(bad);
    CHECK_FALSE(parseRandomSpec(bad, &r, err, sizeof err));
    const std::string e = err;
    CHECK(e.rfind(std::string(bad) + ": ", 0) == 0);
    CHECK(has(e, "rand:SEED[:DATA]"));
  }
}
