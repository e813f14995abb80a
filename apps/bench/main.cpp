// cuetrack-bench: the paper's evaluation protocol over recorded sequences, for
// cuetrack's configurations and OpenCV's trackers on the very same decoded frames.
// Exit code: 0 every sequence was sound and every output was written (a tracker that
// cannot run on a sequence is a finding, reported and listed); 1 a sequence was missing
// or broken, or an output failed; 2 bad command line.
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "AllocCounter.hpp"
#include "Json.hpp"
#include "Options.hpp"
#include "Outputs.hpp"
#include "PeerCache.hpp"
#include "Peers.hpp"
#include "Report.hpp"
#include "Runner.hpp"
#include "Sources.hpp"
#include "TrackerAdapters.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;
using namespace cuetrack::bench;

namespace {

// "dir/Vid_C_juice.avi" -> "Vid_C_juice", "seq/" -> "seq": the name a reader would give.
std::string nameOf(const std::string& spec) {
  std::string s = spec;
  while (s.size() > 1 && s.back() == '/') s.pop_back();
  const size_t slash = s.find_last_of('/');
  if (slash != std::string::npos) s = s.substr(slash + 1);
  const size_t dot = s.find_last_of('.');
  if (dot != std::string::npos && dot > 0) s = s.substr(0, dot);
  return s;
}

std::unique_ptr<BenchTracker> makeTracker(const EntrySpec& spec, std::string* err) {
  if (spec.tracker == "cuetrack") return makeCuetrackBench(spec.config, err);
  return makePeerBench(spec.tracker, err);
}

bool writeText(const std::string& path, const std::string& text, std::string* err) {
  FILE* f = std::fopen(path.c_str(), "wb");
  if (!f) {
    *err = path + ": cannot write";
    return false;
  }
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) {
    *err = path + ": write failed";
    return false;
  }
  return true;
}

}  // namespace

int main(int argc, char** argv) {
  cuetrack::platform::ignoreWriteSignals();
  Options options;
  bool help = false;
  std::string err;
  if (!parseOptions(argc, argv, &options, &help, &err)) {
    std::fprintf(stderr, "cuetrack-bench: %s (see --help)\n", err.c_str());
    return 2;
  }
  if (help) {
    std::fputs(usage().c_str(), stdout);
    return cuetrack::platform::stdoutWritten("cuetrack-bench") ? 0 : 1;
  }

  std::vector<EntryResult> results;
  for (const EntrySpec& e : options.entries) results.push_back({e.tracker, e.config, e.runs, {}});

  const TrackerFactory factory = makeTracker;
  RunOptions runOptions;
  runOptions.seed = options.seed;
  runOptions.resultsDir = options.resultsDir;
  runOptions.allocationCount = &cuetrack::test::allocationCount;
  Progress progress(!options.quiet);
  int failures = 0;

  for (size_t si = 0; si < options.sequences.size(); ++si) {
    const SequenceArg& arg = options.sequences[si];
    Sequence seq;
    std::unique_ptr<FrameSource> source = openSequence(arg, options, &err);
    bool ok = source != nullptr;
    if (ok) {
      ok = loadSequence(*source, options.maxFrames, options.maxMemMiB << 20, &seq, &err);
      if (!ok) seq.name = source->name();
    }
    source.reset();  // decoded: the reader's buffers are no longer needed
    if (ok) ok = sliceSequence(&seq, arg.fromIndex, arg.toIndex, arg.reverse, &err);
    if (!ok) {
      std::fprintf(stderr, "cuetrack-bench: %s (skipped)\n", err.c_str());
      ++failures;
      for (EntryResult& r : results) {
        SequenceResult s;
        s.name = seq.name.empty() ? nameOf(arg.spec) : seq.name;
        s.error = "sequence failed: " + err;
        r.sequences.push_back(s);
      }
      continue;
    }
    if (seq.skippedFrames > 0)
      std::fprintf(stderr, "cuetrack-bench: %s: %d unreadable frames skipped\n", seq.name.c_str(),
                   seq.skippedFrames);
    if (options.rgbOnly)
      for (CachedFrame& f : seq.frames) f.depthMm.clear();
    thinSequence(&seq, options.stride, options.dropPct, options.seed);
    if (seq.droppedFrames > 0)
      std::fprintf(stderr, "cuetrack-bench: %s: %d frames left out (--stride / --drop-frames)\n",
                   seq.name.c_str(), seq.droppedFrames);
    seq.gtHeader = bobotHeader(arg);

    long planned = 0;
    for (const EntrySpec& e : options.entries)
      planned += static_cast<long>(e.runs) * static_cast<long>(seq.frames.size() - 1);
    progress.beginSequence(seq.name, static_cast<int>(si),
                           static_cast<int>(options.sequences.size()), planned);
    for (size_t ei = 0; ei < options.entries.size(); ++ei) {
      const EntrySpec& spec = options.entries[ei];
      const bool cacheable = !options.peerCacheDir.empty() && isPeerName(spec.tracker) &&
                             options.resultsDir.empty();  // result files need the run
      const std::string cachePath =
          cacheable ? peerCachePath(options.peerCacheDir, spec, seq, options.seed) : "";
      SequenceResult r;
      r.name = seq.name;
      r.skippedFrames = seq.skippedFrames;
      if (!cacheable || !loadPeerResult(cachePath, &r)) {
        r = runEntry(spec, seq, factory, runOptions, progress);
        if (cacheable && !savePeerResult(cachePath, r, &err)) {
          std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
          ++failures;
        }
      }
      if (!r.ran) {
        std::fprintf(stderr, "cuetrack-bench: %s on %s: %s\n", results[ei].label().c_str(),
                     seq.name.c_str(), r.error.c_str());
        if (r.sequenceFault) ++failures;
      }
      if (!r.outputError.empty()) ++failures;  // reported by runEntry
      results[ei].sequences.push_back(std::move(r));
    }

    const size_t index = results.front().sequences.size() - 1;
    if (!options.csvDir.empty()) {
      if (!makeDirs(options.csvDir, &err) ||
          !writeOverlapCsv(options.csvDir + "/" + seq.name + ".overlap.csv", results, index,
                           &err)) {
        std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
        ++failures;
      }
    }
    if (!options.plotDir.empty()) {
      if (!makeDirs(options.plotDir, &err) ||
          !writeOverlapPlot(options.plotDir + "/" + seq.name + ".overlap.png", results, index,
                            &err)) {
        std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
        ++failures;
      }
    }
    if (!options.overlayDir.empty() &&
        !writeOverlayFrames(options.overlayDir + "/" + seq.name, seq, results, index, &err)) {
      std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
      ++failures;
    }
    if (!options.videoDir.empty() && (!makeDirs(options.videoDir, &err) ||
                                      !writeOverlayVideo(options.videoDir + "/" + seq.name + ".avi",
                                                         seq, results, index, 30.0, &err))) {
      std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
      ++failures;
    }
  }

  if (!options.plotDir.empty() && !results.empty() && !results.front().sequences.empty()) {
    for (const CurveKind kind : {CurveKind::Success, CurveKind::Precision}) {
      const char* name = kind == CurveKind::Success ? "/success.png" : "/precision.png";
      if (!makeDirs(options.plotDir, &err) ||
          !writeCurvePlot(options.plotDir + name, results, kind, &err)) {
        std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
        ++failures;
      }
    }
  }
  const std::string report = textReport(results);
  errno = 0;
  if (std::fwrite(report.data(), 1, report.size(), stdout) != report.size() ||
      std::fflush(stdout) != 0) {
    std::fprintf(stderr, "cuetrack-bench: stdout: cannot write the report: %s\n",
                 errno ? std::strerror(errno) : "write failed");
    ++failures;
  }
  if (!options.jsonPath.empty() && !writeJson(options.jsonPath.c_str(), results, &err)) {
    std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
    ++failures;
  }
  if (!options.markdownPath.empty() &&
      !writeText(options.markdownPath, markdownReport(results, options.paper), &err)) {
    std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
    ++failures;
  }
  if (failures > 0)
    std::fprintf(stderr, "cuetrack-bench: %d failure(s); see the messages above\n", failures);
  return failures > 0 ? 1 : 0;
}
