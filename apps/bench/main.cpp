// cuetrack-bench: the paper's evaluation protocol over recorded sequences, for
// cuetrack's configurations and OpenCV's trackers on the very same decoded frames.
// Exit code: 0 every sequence was sound and every output was written (a tracker that
// cannot run on a sequence is a finding, reported and listed); 1 a sequence was missing
// or broken, or an output failed; 2 bad command line; 3 interrupted (the figures so far,
// marked partial).
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <memory>
#include <string>
#include <tuple>
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
#include "cuetrack/cli/OutputGuard.hpp"
#if CUETRACK_BENCH_HAVE_SYNTH
#include "cuetrack/drivers/SceneCatalogue.hpp"
#endif
#include "cuetrack/platform/StdoutCheck.hpp"
#include "cuetrack/platform/linux/Signals.hpp"

using namespace cuetrack;
using namespace cuetrack::bench;

namespace {

constexpr int kExitInterrupted = 3;  // SIGINT/SIGTERM/SIGHUP: the figures so far, partial

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

// The name a sequence's output files take, before it is read (the reader's name is the
// file's stem too), with --from/--to/--reverse's suffixes (sliceSequence).
std::string outputName(const SequenceArg& arg) {
  std::string name = nameOf(arg.spec);
  if (arg.fromIndex >= 0) name += ".from" + std::to_string(arg.fromIndex);
  if (arg.toIndex >= 0) name += ".to" + std::to_string(arg.toIndex);
  if (arg.reverse) name += ".rev";
  return name;
}

// Every file and folder the run reads and writes, for the one guard of every tool (exit
// 2 before anything is written): each sequence and its ground truth are inputs; --json,
// --markdown and the files and folders named after each sequence are outputs.
cli::OutputGuard outputGuard(const Options& o) {
  cli::OutputGuard g;
  for (const SequenceArg& a : o.sequences) {
    g.source("sequence", a.spec);
    g.input("--gt", a.gtPath);
  }
  g.output("--json", o.jsonPath);
  g.output("--markdown", o.markdownPath);
  g.outputFolder("--csv", o.csvDir);
  g.outputFolder("--plots", o.plotDir);
  g.outputFolder("--results", o.resultsDir);
  g.outputFolder("--overlay", o.overlayDir);
  g.outputFolder("--video", o.videoDir);
  g.outputFolder("--peer-cache", o.peerCacheDir);
  if (!o.plotDir.empty()) {
    g.output("--plots", o.plotDir + "/success.png");
    g.output("--plots", o.plotDir + "/precision.png");
  }
  for (const SequenceArg& a : o.sequences) {
    const std::string name = outputName(a);
    if (!o.csvDir.empty()) g.output("--csv", o.csvDir + "/" + name + ".overlap.csv");
    if (!o.plotDir.empty()) g.output("--plots", o.plotDir + "/" + name + ".overlap.png");
    if (!o.videoDir.empty()) g.output("--video", o.videoDir + "/" + name + ".avi");
    if (!o.overlayDir.empty()) g.outputFolder("--overlay", o.overlayDir + "/" + name);
    if (!o.resultsDir.empty()) g.outputFolder("--results", o.resultsDir + "/" + name);
  }
  return g;
}

// Decodes, slices and thins one sequence as the options ask; false with *err.
bool prepareSequence(const SequenceArg& arg, const Options& options, Sequence* seq,
                     std::string* err) {
  std::unique_ptr<FrameSource> source = openSequence(arg, options, err);
  bool ok = source != nullptr;
  if (ok) {
    ok = loadSequence(*source, options.maxFrames, options.maxMemMiB << 20, seq, err);
    if (!ok) seq->name = source->name();
  }
  source.reset();  // decoded: the reader's buffers are no longer needed
  if (ok) ok = sliceSequence(seq, arg.fromIndex, arg.toIndex, arg.reverse, err);
  if (!ok) {
    if (seq->name.empty()) seq->name = nameOf(arg.spec);
    return false;
  }
  if (seq->skippedFrames > 0)
    std::fprintf(stderr, "cuetrack-bench: %s: %d unreadable frames skipped\n", seq->name.c_str(),
                 seq->skippedFrames);
  if (options.rgbOnly)
    for (CachedFrame& f : seq->frames) f.depthMm.clear();
  thinSequence(seq, options.stride, options.dropPct, options.seed);
  if (seq->droppedFrames > 0)
    std::fprintf(stderr, "cuetrack-bench: %s: %d frames left out (--stride / --drop-frames)\n",
                 seq->name.c_str(), seq->droppedFrames);
  seq->gtHeader = bobotHeader(arg);
  return true;
}

// Every entry on one sequence (a peer's result from the cache when it is there); the
// number of failures.
int runEntries(const Sequence& seq, const Options& options, const RunOptions& runOptions,
               Progress& progress, std::vector<EntryResult>* results) {
  const TrackerFactory factory = makeTracker;
  int failures = 0;
  std::string err;
  for (size_t ei = 0; ei < options.entries.size(); ++ei) {
    const EntrySpec& spec = options.entries[ei];
    if (platform::stopRequested()) {  // the rest of the table says so, row by row
      SequenceResult r;
      r.name = seq.name;
      r.error = "interrupted";
      (*results)[ei].sequences.push_back(std::move(r));
      continue;
    }
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
      std::fprintf(stderr, "cuetrack-bench: %s on %s: %s\n", (*results)[ei].label().c_str(),
                   seq.name.c_str(), r.error.c_str());
      if (r.sequenceFault) ++failures;
    }
    if (!r.outputError.empty()) ++failures;  // reported by runEntry
    (*results)[ei].sequences.push_back(std::move(r));
  }
  return failures;
}

// One output of a sequence or of the whole run: false after its line on stderr.
bool reported(bool ok, const std::string& err) {
  if (!ok) std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
  return ok;
}

// --csv, --plots, --overlay, --video for one sequence; the number of failures.
int writeSequenceOutputs(const Sequence& seq, const Options& options,
                         const std::vector<EntryResult>& results, const cli::OutputGuard& guard) {
  const size_t index = results.front().sequences.size() - 1;
  int failures = 0;
  std::string err;
  // The reader may name a sequence otherwise than its file: checked again, by its name.
  for (const auto& [what, dir, suffix] : {std::tuple<const char*, const std::string&, const char*>{
                                              "--csv", options.csvDir, ".overlap.csv"},
                                          {"--plots", options.plotDir, ".overlap.png"},
                                          {"--overlay", options.overlayDir, ""},
                                          {"--video", options.videoDir, ".avi"}}) {
    if (!dir.empty() && !guard.checkLater(what, dir + "/" + seq.name + suffix, &err)) {
      reported(false, err + " (nothing written for " + seq.name + ")");
      return 1;
    }
  }
  if (!options.csvDir.empty())
    failures += !reported(
        makeDirs(options.csvDir, &err) &&
            writeOverlapCsv(options.csvDir + "/" + seq.name + ".overlap.csv", results, index, &err),
        err);
  if (!options.plotDir.empty())
    failures += !reported(makeDirs(options.plotDir, &err) &&
                              writeOverlapPlot(options.plotDir + "/" + seq.name + ".overlap.png",
                                               results, index, &err),
                          err);
  if (!options.overlayDir.empty())
    failures += !reported(
        writeOverlayFrames(options.overlayDir + "/" + seq.name, seq, results, index, &err), err);
  if (!options.videoDir.empty())
    failures += !reported(makeDirs(options.videoDir, &err) &&
                              writeOverlayVideo(options.videoDir + "/" + seq.name + ".avi", seq,
                                                results, index, 30.0, &err),
                          err);
  return failures;
}

// The success and precision plots, the report on stdout, --json and --markdown; the
// number of failures.
int writeFinalOutputs(const Options& options, const std::vector<EntryResult>& results) {
  int failures = 0;
  std::string err;
  if (!options.plotDir.empty() && !results.empty() && !results.front().sequences.empty()) {
    for (const CurveKind kind : {CurveKind::Success, CurveKind::Precision}) {
      const char* name = kind == CurveKind::Success ? "/success.png" : "/precision.png";
      failures += !reported(makeDirs(options.plotDir, &err) &&
                                writeCurvePlot(options.plotDir + name, results, kind, &err),
                            err);
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
  if (!options.jsonPath.empty())
    failures += !reported(writeJson(options.jsonPath.c_str(), results, &err), err);
  if (!options.markdownPath.empty())
    failures += !reported(
        writeText(options.markdownPath, markdownReport(results, options.paper), &err), err);
  return failures;
}

}  // namespace

int main(int argc, char** argv) {
  cuetrack::platform::installStopSignals();  // first: a stop at any moment ends as --help says
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

#if CUETRACK_BENCH_HAVE_SYNTH
  for (const SequenceArg& a : options.sequences) {  // an unknown scene: a bad command line
    char why[800];
    if (!knownSceneSource(a.spec.c_str(), why, sizeof why)) {
      std::fprintf(stderr, "cuetrack-bench: %s\n", why);
      return 2;
    }
  }
#endif
  const cli::OutputGuard guard = outputGuard(options);
  if (!guard.check(&err)) {
    std::fprintf(stderr, "cuetrack-bench: %s\n", err.c_str());
    return 2;
  }

  std::vector<EntryResult> results;
  for (const EntrySpec& e : options.entries) results.push_back({e.tracker, e.config, e.runs, {}});
  RunOptions runOptions;
  runOptions.seed = options.seed;
  runOptions.resultsDir = options.resultsDir;
  runOptions.allocationCount = &cuetrack::test::allocationCount;
  Progress progress(!options.quiet);
  int failures = 0;

  size_t done = 0;  // sequences every entry ran on
  for (size_t si = 0; si < options.sequences.size() && !platform::stopRequested(); ++si) {
    const SequenceArg& arg = options.sequences[si];
    Sequence seq;
    if (!prepareSequence(arg, options, &seq, &err)) {
      if (platform::stopRequested()) break;  // interrupted while decoding: not a failure
      std::fprintf(stderr, "cuetrack-bench: %s (skipped)\n", err.c_str());
      ++failures;
      for (EntryResult& r : results) {
        SequenceResult s;
        s.name = seq.name;
        s.error = "sequence failed: " + err;
        r.sequences.push_back(s);
      }
      continue;
    }
    long planned = 0;
    for (const EntrySpec& e : options.entries)
      planned += static_cast<long>(e.runs) * static_cast<long>(seq.frames.size() - 1);
    progress.beginSequence(seq.name, static_cast<int>(si),
                           static_cast<int>(options.sequences.size()), planned);
    failures += runEntries(seq, options, runOptions, progress, &results);
    failures += writeSequenceOutputs(seq, options, results, guard);
    ++done;
  }
  const int stopSignal = platform::stopSignal();
  if (stopSignal != 0) {
    const std::string partial = "interrupted by signal " + std::to_string(stopSignal) + " after " +
                                std::to_string(done) + " of " +
                                std::to_string(options.sequences.size()) + " sequences";
    for (EntryResult& r : results) r.partial = partial;
  }

  failures += writeFinalOutputs(options, results);
  if (stopSignal != 0) {
    std::fprintf(stderr, "cuetrack-bench: %s; the figures so far, marked partial%s\n",
                 results.empty() ? "interrupted" : results.front().partial.c_str(),
                 failures > 0 ? " (and failures: see above)" : "");
    return kExitInterrupted;
  }
  if (failures > 0)
    std::fprintf(stderr, "cuetrack-bench: %d failure(s); see the messages above\n", failures);
  return failures > 0 ? 1 : 0;
}
