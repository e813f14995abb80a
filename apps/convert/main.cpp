// cuetrack-convert (built by apps/synth/CMakeLists.txt): converts any frame source (see --help) to
// a fakenect recording or an RGB-D folder, or measures how fast a source reads (--bench).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <memory>
#include <string>
#include <vector>

#include "SequenceOut.hpp"
#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"
#include "cuetrack/drivers/OpenSource.hpp"
#include "cuetrack/drivers/SceneCatalogue.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;
namespace cli = cuetrack::cli;

namespace {

FrameSlot gSlot;  // 1.5 MiB: static storage

const char* kAbout =
    "Converts a frame source to a fakenect recording (default), an RGB-D folder, an OTB\n"
    "folder or an .avi, or measures how fast it reads (--bench).\n"
    "  cuetrack-convert SOURCE --out DIR [--format fakenect|rgbd|otb|avi] [options]\n"
    "  cuetrack-convert SOURCE --bench [options]";

std::string footer() {
  return std::string("SOURCE is one of:\n") + frameSourceHelp() +
         "Outputs are whole or absent: a failed or interrupted run (SIGINT/SIGTERM/SIGHUP)\n"
         "removes the folder it created, or the .avi and .gt.txt it was writing (an earlier\n"
         ".avi replaced with --force stays until the new one is whole).\n"
         "formats: fakenect (default), rgbd (RGB-D folder), otb (OTB folder, colour),\n"
         "         avi (BoBoT-style MJPG video; --out is the .avi path)\n"
         "exit codes: 0 ok, 1 read/write failed (stdout too) or interrupted, 2 bad arguments\n"
         "  (an option given twice, an unknown scene, an output that would overwrite an\n"
         "  input, --force or not)";
}

}  // namespace

int main(int argc, char** argv) {
  // First: a stop at any moment ends as --help says (a partial output removed, exit 1).
  cuetrack::platform::installStopSignals();
  std::vector<std::string> sources;
  std::string out, format = "fakenect", gt;
  bool bench = false, force = false;
  SourceOptions opt;
  char err[1024] = "";
  cli::Command cmd("cuetrack-convert", kAbout, footer());
  cmd.positionals("SOURCE", "the frames to read (below)", &sources);
  cmd.text("--out", "DIR", "the folder to write (the .avi file for --format avi)", &out);
  cmd.text("--format", "FORMAT", "fakenect (default), rgbd, otb or avi", &format);
  cmd.number("--frames", "N", "at most N frames", 1, 10000000, &opt.maxFrames);
  cmd.option("--seed", "S", "seed of synthetic scenes",
             [&opt](const std::string& v) { return cli::seed(v, &opt.seed); });
  cmd.text("--gt", "PATH", "ground truth overriding the source's own", &gt);
  cmd.flag("--skip-bad", "skip unreadable or damaged frames (counted) instead of stopping",
           &opt.skipBadFrames);
  cmd.flag("--bench", "read every frame, print frames/s (nothing written)", &bench);
  cmd.flag("--force", "overwrite an .avi and its .gt.txt (never a folder holding a recording)",
           &force);
  if (const int rc = cmd.parse(argc, argv); rc >= 0) return rc;
  if (sources.size() > 1)
    return cmd.fail("more than one SOURCE ('" + sources[0] + "', '" + sources[1] + "')");
  if (sources.empty() || (!bench && out.empty()))
    return cmd.fail("SOURCE and --out (or --bench) are required");
  const char* spec = sources[0].c_str();
  if (!knownSceneSource(spec, err, sizeof err)) return cmd.fail(err);  // exit 2, every tool
  if (!gt.empty()) opt.gtPath = gt.c_str();
  if (!bench) {
    cli::OutputGuard inputs;
    inputs.source("SOURCE", spec);
    inputs.input("--gt", gt);
    if (const int rc = checkSequenceOut("cuetrack-convert", format.c_str(), out.c_str(), inputs))
      return rc;
  }
  std::unique_ptr<FrameSource> src = openFrameSource(spec, opt, err, sizeof err);
  if (!src) {
    std::fprintf(stderr, "cuetrack-convert: %s\n", err);
    return cli::kExitFailed;
  }
  if (bench) {
    // Reading only: decode + convert into the slot, as the tracker's input path does.
    int n = 0;
    // Wall and process CPU time: the CPU figure holds on a shared, loaded machine.
    const auto t0 = std::chrono::steady_clock::now();
    const std::clock_t c0 = std::clock();
    for (;;) {
      if (cuetrack::platform::stopRequested()) {
        std::fprintf(stderr, "cuetrack-convert: interrupted after %d frames\n", n);
        return cli::kExitFailed;
      }
      const ReadStatus st = src->next(gSlot);
      if (st == ReadStatus::End) break;
      if (st == ReadStatus::Error) {
        std::fprintf(stderr, "cuetrack-convert: %s\n", src->error());
        return cli::kExitFailed;
      }
      ++n;
    }
    const double s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
    std::printf(
        "%s: %d frames %dx%d: wall %.1f frames/s (%.2f ms/frame), cpu %.1f frames/s "
        "(%.2f ms/frame), skipped %d\n",
        src->name(), n, gSlot.rgb.width(), gSlot.rgb.height(), n > 0 ? n / s : 0.0,
        n > 0 ? 1e3 * s / n : 0.0, n > 0 && cpu > 0 ? n / cpu : 0.0, n > 0 ? 1e3 * cpu / n : 0.0,
        src->skippedFrames());
    if (!cuetrack::platform::stdoutWritten("cuetrack-convert")) return cli::kExitFailed;
    return n > 0 ? 0 : cli::kExitFailed;
  }
  int n = 0;
  if (const int rc = writeSequence("cuetrack-convert", *src, format.c_str(), out.c_str(),
                                   src->name(), force, gSlot, &n);
      rc != 0)
    return rc;
  std::printf("cuetrack-convert: wrote %d frames of %s to %s (%s), skipped %d\n", n, spec,
              out.c_str(), format.c_str(), src->skippedFrames());
  return cuetrack::platform::stdoutWritten("cuetrack-convert") ? 0 : cli::kExitFailed;
}
