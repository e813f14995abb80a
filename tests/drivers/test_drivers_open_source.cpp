// openFrameSource(): format detection and its one-line errors.
#include <catch2/catch.hpp>

#include <memory>
#include <string>

#include "TempDir.hpp"
#include "cuetrack/drivers/FakenectReader.hpp"
#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;
using cuetrack::test::TempDir;

TEST_CASE("openFrameSource opens synth and fakenect specs", "[open]") {
  char err[512] = "";
  SourceOptions opt;
  auto f = std::make_unique<FrameSlot>();
  auto s = openFrameSource("synth:occlusion:4", opt, err, sizeof err);
  REQUIRE(s);
  CHECK(s->frameCount() == 4);
  CHECK(std::string(s->name()) == "occlusion");
  opt.maxFrames = 2;
  s = openFrameSource("synth:moving", opt, err, sizeof err);
  REQUIRE(s);
  int n = 0;
  while (s->next(*f) == ReadStatus::Ok) ++n;
  CHECK(n == 2);

  TempDir tmp;
  {
    SceneSpec spec;
    REQUIRE(makeScene("moving", &spec));
    spec.frameCount = 3;
    auto src = std::make_unique<SyntheticSource>(spec, 1);
    FakenectWriter w;
    if (!(w.open((tmp / "rec").c_str(), "moving"))) FAIL(w.error());
    while (src->next(*f) == ReadStatus::Ok)
      if (!(w.write(*f))) FAIL(w.error());
    if (!(w.close())) FAIL(w.error());
  }
  s = openFrameSource((tmp / "rec").c_str(), SourceOptions{}, err, sizeof err);
  REQUIRE(s);
  CHECK(s->frameCount() == 3);

  // A drawn scene in the generated room: any build, the target in the first frame.
  opt.maxFrames = 2;
  s = openFrameSource("rand:5", opt, err, sizeof err);
  REQUIRE(s);
  CHECK(std::string(s->name()) == "rand-5");
  REQUIRE(s->next(*f) == ReadStatus::Ok);
  CHECK(f->hasGroundTruth);
  CHECK_FALSE(f->groundTruth.empty());
  CHECK(f->hasDepth);
}

TEST_CASE("openFrameSource errors are one line naming the spec", "[open][bad]") {
  char err[512] = "";
  TempDir tmp;
  struct Case {
    std::string spec, expect;
  };
  const Case cases[] = {
      {"synth:nope", "unknown scene 'nope'"},
      {"synth:moving:0", "is not a number"},
      {"synth:moving:x", "is not a number"},
      {"rand:x", "the seed 'x' is not a whole number"},
      {"rand:2:" + tmp / "nodata", frameSourcesHaveOpenCv() ? "has no kinect-stills/ and otb/"
                                                            : "need a host build with OpenCV"},
      {tmp / "absent", "no such file or folder"},
      {tmp.path(), "not a recording"},
      {tmp / "x.avi", "no such file"},
      {"/dev/null", "not a recording (a device"},  // it exists: not "no such file"
      {"/tmp/" + std::string(1000, 'd'), "path longer than 900 characters (1005)"},
      {"", "no frame source"},
  };
  for (const Case& c : cases) {
    INFO(c.spec);
    CHECK_FALSE(openFrameSource(c.spec.c_str(), SourceOptions{}, err, sizeof err));
    const std::string e = err;
    CHECK(e.find(c.expect) != std::string::npos);
    CHECK(e.find('\n') == std::string::npos);
  }
  test::writeText(tmp / "notes.txt", "hello");
  CHECK_FALSE(openFrameSource((tmp / "notes.txt").c_str(), SourceOptions{}, err, sizeof err));
  CHECK(std::string(err).find("unknown format") != std::string::npos);
  if (!frameSourcesHaveOpenCv()) {
    test::writeText(tmp / "v.avi", "x");
    CHECK_FALSE(openFrameSource((tmp / "v.avi").c_str(), SourceOptions{}, err, sizeof err));
    CHECK(std::string(err).find("needs a host build with OpenCV") != std::string::npos);
    test::writeText(tmp / "v.mp4", "x");
    CHECK_FALSE(openFrameSource((tmp / "v.mp4").c_str(), SourceOptions{}, err, sizeof err));
    CHECK(std::string(err).find("a video needs a host build with OpenCV") != std::string::npos);
    CHECK_FALSE(openFrameSource("camera", SourceOptions{}, err, sizeof err));
    CHECK(std::string(err) ==
          "camera: a V4L2 camera needs a host build with OpenCV (this build "
          "has none)");
    char device[64];
    CHECK_FALSE(findDefaultCamera(device, sizeof device));
  }
  // Any video by its extension, any case: not "unknown format" (it decodes or it is damaged).
  test::writeText(tmp / "phone.MOV", "not a video");
  CHECK_FALSE(openFrameSource((tmp / "phone.MOV").c_str(), SourceOptions{}, err, sizeof err));
  CHECK(std::string(err).find("unknown format") == std::string::npos);
  // A panned still: decoded by OpenCV; its own errors name the image at fault.
  const std::string pan =
      "pan:" + tmp / "none.png" + "," + tmp / "none.png" + ",1,1,8,8,500,500,4,4";
  CHECK_FALSE(openFrameSource(pan.c_str(), SourceOptions{}, err, sizeof err));
  CHECK(std::string(err).find(frameSourcesHaveOpenCv()
                                  ? "none.png: cannot decode image"
                                  : "needs a host build with OpenCV") != std::string::npos);
  // A scene in a real still: the same.
  const std::string still =
      "still:" + tmp / "none.png" + "," + tmp / "none.png" + ",500,500,4,4:moving@1,1,50";
  CHECK_FALSE(openFrameSource(still.c_str(), SourceOptions{}, err, sizeof err));
  CHECK(std::string(err).find(frameSourcesHaveOpenCv()
                                  ? "none.png: cannot decode image"
                                  : "needs a host build with OpenCV") != std::string::npos);
}
