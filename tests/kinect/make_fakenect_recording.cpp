// Test helper: writes a synthetic scene as a fakenect recording (with the project's
// FakenectWriter), optionally with a pause in the timestamps to imitate a stalled stream.
//   make_fakenect_recording OUT SCENE FRAMES [PAUSE_AFTER_FRAME PAUSE_MS]
#include <cstdio>
#include <cstdlib>

#include "cuetrack/drivers/FakenectWriter.hpp"
#include "cuetrack/drivers/SyntheticSource.hpp"

using namespace cuetrack;

namespace {
FrameSlot gSlot;
FakenectWriter gWriter;
}  // namespace

int main(int argc, char** argv) {
  if (argc != 4 && argc != 6) {
    std::fprintf(stderr, "usage: %s OUT SCENE FRAMES [PAUSE_AFTER_FRAME PAUSE_MS]\n", argv[0]);
    return 1;
  }
  SceneSpec spec;
  if (!makeScene(argv[2], &spec)) {
    std::fprintf(stderr, "%s: unknown scene '%s'\n", argv[0], argv[2]);
    return 1;
  }
  spec.frameCount = std::atoi(argv[3]);
  const int pauseAfter = argc == 6 ? std::atoi(argv[4]) : -1;
  const uint64_t pauseUs = argc == 6 ? static_cast<uint64_t>(std::atoi(argv[5])) * 1000u : 0;
  static SyntheticSource source(spec, 7);
  if (!gWriter.open(argv[1])) {
    std::fprintf(stderr, "%s: %s\n", argv[0], gWriter.error());
    return 1;
  }
  int frames = 0;
  while (source.next(gSlot) == ReadStatus::Ok) {
    if (pauseAfter >= 0 && gSlot.index >= pauseAfter) gSlot.timeUs += pauseUs;
    if (!gWriter.write(gSlot)) {
      std::fprintf(stderr, "%s: %s\n", argv[0], gWriter.error());
      return 1;
    }
    ++frames;
  }
  if (!gWriter.close()) {
    std::fprintf(stderr, "%s: %s\n", argv[0], gWriter.error());
    return 1;
  }
  std::printf("%s: %d frames of '%s'\n", argv[1], frames, argv[2]);
  return 0;
}
