// cuetrack-synth: writes a synthetic RGB-D scene with exact ground truth as a
// fakenect recording or an RGB-D folder.

#include <cstdio>
#include <cstdlib>
#include <memory>
#include <string>

#include "SequenceOut.hpp"
#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;
namespace cli = cuetrack::cli;

namespace {

FrameSlot gSlot;  // 1.5 MiB: static storage

const char* kAbout =
    "Writes a synthetic RGB-D sequence with exact ground truth (groundtruth.txt,\n"
    "BoBoT format) as a fakenect recording (default; INDEX.txt, r-/d-/a- files)\n"
    "or an RGB-D folder (rgb/, depth/ 16-bit PNG mm, intrinsics.txt; needs OpenCV);\n"
    "otb (img/*.jpg + groundtruth_rect.txt) and avi (MJPG video + .gt.txt, --out is\n"
    "the .avi path) are colour only, for the RGB benchmarks' formats (need OpenCV).\n"
    "A scene is a named one below, or rand:SEED[:DATA], one drawn from SEED out of the\n"
    "randomised scenes (docs/recordings.md); DATA, the shared data folder, adds real\n"
    "Kinect stills as backdrops and textures cut from real videos (needs OpenCV).\n"
    "  cuetrack-synth --scene NAME --out DIR [--format fakenect|rgbd|otb|avi]\n"
    "                 [--frames N] [--seed S] [--size WxH] [--force]\n"
    "  cuetrack-synth --list";

const char* kExitCodes =
    "Outputs are whole or absent: a failed or interrupted run (SIGINT/SIGTERM/SIGHUP)\n"
    "removes the folder it created, or the .avi and .gt.txt it was writing (an earlier\n"
    ".avi replaced with --force stays until the new one is whole).\n"
    "exit codes: 0 ok, 1 write failed (stdout too) or interrupted, 2 bad arguments (an\n"
    "option given twice, an unknown scene, an output over an input, --force or not)";

// The catalogue's rows for --help, a name and its summary a line.
std::string sceneTable() {
  std::string t = "\n\nscenes (--list: the names alone):\n";
  for (int i = 0; i < sceneCount(); ++i) {
    const SceneEntry* e = sceneEntry(i);
    std::string name = e->name;
    name.resize(name.size() < 16 ? 16 : name.size() + 1, ' ');
    t += "  " + name + e->summary + "\n";
  }
  t.pop_back();
  return t;
}

}  // namespace

int main(int argc, char** argv) {
  // First: a stop at any moment ends as --help says (a partial output removed, exit 1).
  cuetrack::platform::installStopSignals();
  std::string scene, out, format = "fakenect";
  int frames = -1, width = 640, height = 480;
  uint64_t seed = 1;
  bool force = false, list = false;
  char err[600] = "";
  cli::Command cmd("cuetrack-synth", std::string(kAbout) + sceneTable(), kExitCodes);
  cmd.text("--scene", "NAME", "a scene below or rand:SEED[:DATA] (150 frames at 30 fps)", &scene);
  cmd.text("--out", "DIR", "the folder to write (the .avi file for --format avi)", &out);
  cmd.text("--format", "FORMAT", "fakenect (default), rgbd, otb or avi", &format);
  cmd.number("--frames", "N", "number of frames (1..100000)", 1, 100000, &frames);
  cmd.option("--seed", "S", "sensor-noise seed (same seed, same bytes)",
             [&seed](const std::string& v) { return cli::seed(v, &seed); });
  cmd.option("--size", "WxH", "image size (default 640x480, at most 640x480)",
             [&](const std::string& v) {
               return cli::imageSize(v, 8, kMaxImageWidth, kMaxImageHeight, &width, &height);
             });
  cmd.flag("--force", "overwrite an .avi and its .gt.txt (never a folder holding a recording)",
           &force);
  cmd.flag("--list", "the scenes, one a line", &list);
  if (const int rc = cmd.parse(argc, argv); rc >= 0) return rc;
  if (list) {
    for (int k = 0; k < sceneCount(); ++k) std::printf("%s\n", sceneName(k));
    return cuetrack::platform::stdoutWritten("cuetrack-synth") ? 0 : cli::kExitFailed;
  }
  if (scene.empty() || out.empty()) return cmd.fail("--scene and --out are required (see --help)");
  cli::OutputGuard inputs;  // rand:SEED:DATA reads DATA's stills
  if (scene.rfind("rand:", 0) == 0) inputs.source("--scene", scene);
  if (const int rc = checkSequenceOut("cuetrack-synth", format.c_str(), out.c_str(), inputs))
    return rc;
  std::unique_ptr<FrameSource> src;
  if (scene.rfind("rand:", 0) == 0) {
    // Drawn scenes come through the readers' one factory (the stills need OpenCV).
    if (width != 640 || height != 480) return cmd.fail("--size is for the named scenes only");
    SourceOptions opt;
    opt.seed = seed;
    opt.maxFrames = frames > 0 ? frames : -1;
    src = openFrameSource(scene.c_str(), opt, err, sizeof err);
    if (!src) return cmd.fail(err);
  } else {
    SceneSpec spec;
    if (!makeScene(scene.c_str(), &spec, err, sizeof err)) return cmd.fail(err);
    if (frames > 0) spec.frameCount = frames;
    spec.width = width;
    spec.height = height;
    src = std::make_unique<SyntheticSource>(spec, seed);
  }
  int n = 0;
  if (const int rc = writeSequence("cuetrack-synth", *src, format.c_str(), out.c_str(), src->name(),
                                   force, gSlot, &n);
      rc != 0)
    return rc;
  std::printf("cuetrack-synth: wrote %d frames of '%s' (%dx%d, seed %llu) to %s (%s)\n", n,
              src->name(), gSlot.rgb.width(), gSlot.rgb.height(),
              static_cast<unsigned long long>(seed), out.c_str(), format.c_str());
  return cuetrack::platform::stdoutWritten("cuetrack-synth") ? 0 : cli::kExitFailed;
}
