#include "Sources.hpp"

#include <cstdio>
#include <cstring>

#if CUETRACK_BENCH_HAVE_SYNTH
#include "cuetrack/drivers/SyntheticSource.hpp"
#endif
#if CUETRACK_BENCH_HAVE_READERS
#include "cuetrack/drivers/OpenSource.hpp"
#endif

namespace cuetrack::bench {
namespace {

bool endsWith(const std::string& s, const char* suffix) {
  const size_t n = std::strlen(suffix);
  return s.size() >= n && s.compare(s.size() - n, n, suffix) == 0;
}

// Scenes keep their own seed: every tracker run sees the same frames.
constexpr uint64_t kSceneSeed = 1;

}  // namespace

std::unique_ptr<FrameSource> openSequence(const SequenceArg& arg, const Options& options,
                                          std::string* err) {
#if CUETRACK_BENCH_HAVE_READERS
  // Every format, synth:<scene> included, through the project's one factory.
  SourceOptions so;
  so.skipBadFrames = options.skipBadFrames;
  so.gtPath = arg.gtPath.empty() ? nullptr : arg.gtPath.c_str();
  so.maxFrames = options.maxFrames > 0 ? options.maxFrames : -1;
  so.seed = kSceneSeed;
  char buf[512] = "";
  std::unique_ptr<FrameSource> source = openFrameSource(arg.spec.c_str(), so, buf, sizeof buf);
  if (!source) *err = buf[0] ? buf : arg.spec + ": cannot open";
  return source;
#else
  if (arg.spec.rfind("synth:", 0) == 0) {
#if !CUETRACK_BENCH_HAVE_SYNTH
    *err = arg.spec + ": this build has no synthetic scenes (drivers/synth)";
    return nullptr;
#else
    const std::string scene = arg.spec.substr(6);
    SceneSpec spec;
    char why[512];
    if (!makeScene(scene.c_str(), &spec, why, sizeof why)) {
      *err = arg.spec + ": " + why;
      return nullptr;
    }
    if (options.maxFrames > 0 && options.maxFrames < spec.frameCount)
      spec.frameCount = options.maxFrames;
    return std::make_unique<SyntheticSource>(spec, kSceneSeed);
#endif
  }
  *err = arg.spec + ": this build has no recorded-sequence readers (drivers/recorded)";
  return nullptr;
#endif
}

std::string bobotHeader(const SequenceArg& arg) {
  std::string gt = arg.gtPath;
  if (gt.empty() && endsWith(arg.spec, ".avi"))
    gt = arg.spec.substr(0, arg.spec.size() - 4) + ".gt.txt";
  if (gt.empty()) return "";
  FILE* f = std::fopen(gt.c_str(), "rb");
  if (!f) return "";
  char line[1024] = "";
  if (!std::fgets(line, sizeof line, f)) line[0] = '\0';
  std::fclose(f);
  std::string h = line;
  while (!h.empty() && (h.back() == '\n' || h.back() == '\r')) h.pop_back();
  return h;
}

}  // namespace cuetrack::bench
