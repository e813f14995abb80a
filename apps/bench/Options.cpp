#include "Options.hpp"

#include <cerrno>
#include <cstdlib>
#include <cstring>

#include "Peers.hpp"
#include "TrackerAdapters.hpp"
#include "cuetrack/core/TrackerConfig.hpp"
#include "cuetrack/platform/OptionOnce.hpp"

namespace cuetrack::bench {
namespace {

// Every comma-separated part, empty ones included ("a,,b" -> a, "", b).
std::vector<std::string> splitComma(const std::string& s) {
  std::vector<std::string> out;
  size_t start = 0;
  while (start <= s.size()) {
    const size_t comma = s.find(',', start);
    const size_t end = comma == std::string::npos ? s.size() : comma;
    out.push_back(s.substr(start, end - start));
    if (comma == std::string::npos) break;
    start = comma + 1;
  }
  return out;
}

bool parseCount(const char* text, long min, long max, long* out) {
  if (!text || !*text) return false;
  errno = 0;
  char* end = nullptr;
  const long v = std::strtol(text, &end, 10);
  if (errno != 0 || *end != '\0' || v < min || v > max) return false;
  *out = v;
  return true;
}

}  // namespace

const char* usage() {
  return "usage: cuetrack-bench [options] SEQUENCE...\n"
         "Runs trackers over recorded sequences with the protocol of Garcia et al. 2012:\n"
         "initialise at the first ground-truth box, track, score overlap / hit / PASCAL /\n"
         "centre distance, average over runs (seeds).\n"
         "\n"
         "SEQUENCE: a BoBoT video (NAME.avi, ground truth NAME.gt.txt beside it), an RGB-D\n"
         "  folder, an OTB folder, a fakenect recording (groundtruth.txt beside INDEX.txt),\n"
         "  or synth:<scene>. A missing or broken sequence is reported and skipped.\n"
         "\n"
         "  --gt FILE          ground truth for the next SEQUENCE\n"
         "  --tracker T[,T]    cuetrack, opencv-kcf, opencv-csrt, opencv-mil, opencv-boosting,\n"
         "                     opencv-medianflow, opencv-mosse, opencv-tld, or opencv-all\n"
         "                     (repeatable; default cuetrack)\n"
         "  --config C[,C]     cuetrack configuration: 1.1 ... 1.4, 2.1 ... 2.5, best, or a\n"
         "                     preset with a beyond-the-paper switch off: best-nolost,\n"
         "                     best-fixedsize, best-nofastmotion, best-nocorrelation,\n"
         "                     best-noocclusion;\n"
         "                     or a paper preset with 2D negatives centred:\n"
         "                     1.1-centrednegatives; or best-filter (the correlation\n"
         "                     filter as the correlation cue, not the gray template)\n"
         "                     (repeatable; default best)\n"
         "  --runs N           runs (seeds seed .. seed+N-1) per tracker (default 10)\n"
         "  --peer-runs N      runs for the OpenCV peers (default: --runs)\n"
         "  --seed S           first seed (default 1)\n"
         "  --frames N         use only the first N frames of each sequence\n"
         "  --stride K         a K times slower camera: track every K-th frame after the\n"
         "                     first box (the others are neither tracked nor scored)\n"
         "  --drop-frames PCT  a lossy link: drop PCT percent of the frames at random\n"
         "                     (the same ones for every tracker and run, from --seed)\n"
         "  --from F, --to T   for the next SEQUENCE: only its frames with index F .. T\n"
         "                     (the track begins at the first ground-truth box from F on)\n"
         "  --reverse          for the next SEQUENCE: play it backwards, from its last\n"
         "                     ground-truth box (list a file several times with different\n"
         "                     --from / --to / --reverse for OTB-style temporal robustness)\n"
         "  --skip-bad-frames  let readers skip unreadable frames (counted) instead of failing\n"
         "  --rgb-only         drop the depth of every sequence (best then runs 2D; 2.x fail)\n"
         "  --max-mem MIB      memory for one decoded sequence (default 4096)\n"
         "  --json FILE        figures in the schema of docs/bench-json.md\n"
         "  --markdown FILE    the tables as Markdown\n"
         "  --paper table1|table3  put the paper's figures beside ours in the Markdown\n"
         "  --csv DIR          per-frame overlaps, DIR/<sequence>.overlap.csv\n"
         "  --plots DIR        overlap-over-time plots, DIR/<sequence>.overlap.png\n"
         "  --results DIR      BoBoT result files, DIR/<sequence>/<tracker>[-<config>].run<n>.txt\n"
         "                     (n = 1.. for seeds seed..)\n"
         "  --overlay DIR      frames with the boxes of run 1 drawn, DIR/<sequence>/NNNNNN.jpg\n"
         "  --video DIR        the same as one video per sequence, DIR/<sequence>.avi (Motion\n"
         "                     JPEG, 30 fps), with a legend of the trackers' colours\n"
         "  --quiet            no progress on stderr\n"
         "exit codes: 0 every sequence was sound and every output was written (a tracker\n"
         "  that cannot run on a sequence is reported and listed, not a failure); 1 a\n"
         "  sequence was missing or broken (unreadable, no ground truth, a first box outside\n"
         "  the image, frames changing size) or an output (stdout, --json, --markdown, --csv,\n"
         "  --plots, --results, --overlay, --video) failed: each is reported and the rest\n"
         "  goes on; 2 bad command line\n";
}

bool parseOptions(int argc, const char* const* argv, Options* o, bool* help, std::string* err) {
  *help = false;
  std::vector<std::string> trackers, configs;
  SequenceArg pending;  // --gt, --from, --to, --reverse wait for their SEQUENCE
  // The run-wide settings come once; --tracker and --config add to their lists, and the
  // per-sequence ones (--gt, --from, ...) apply to the next SEQUENCE each time.
  static const char* const kOnce[] = {"--runs",
                                      "--peer-runs",
                                      "--frames",
                                      "--max-mem",
                                      "--seed",
                                      "--json",
                                      "--markdown",
                                      "--csv",
                                      "--plots",
                                      "--results",
                                      "--overlay",
                                      "--paper",
                                      "--skip-bad-frames",
                                      "--rgb-only",
                                      "--quiet"};
  platform::OptionOnce once;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    for (const char* name : kOnce) {
      char twice[64];
      if (a == name && !once.first(argv[i], twice, sizeof twice)) {
        *err = twice;
        return false;
      }
    }
    auto value = [&](const char** v) {
      if (i + 1 >= argc) {
        *err = a + " needs a value";
        return false;
      }
      *v = argv[++i];
      return true;
    };
    const char* v = nullptr;
    long n = 0;
    if (a == "-h" || a == "--help") {
      *help = true;
      return true;
    } else if (a == "--gt") {
      if (!value(&v)) return false;
      pending.gtPath = v;
    } else if (a == "--tracker") {
      if (!value(&v)) return false;
      for (const std::string& t : splitComma(v)) {
        if (t.empty()) {
          *err = std::string("--tracker '") + v + "': an empty tracker name";
          return false;
        }
        if (t == "opencv-all") {
          for (int p = 0; p < kNumPeers; ++p) trackers.push_back(peerName(p));
        } else if (t == "cuetrack" || isPeerName(t)) {
          trackers.push_back(t);
        } else {
          *err = "--tracker: unknown tracker '" + t + "'";
          return false;
        }
      }
    } else if (a == "--config") {
      if (!value(&v)) return false;
      for (const std::string& c : splitComma(v)) {
        if (c.empty()) {
          *err = std::string("--config '") + v + "': an empty configuration name";
          return false;
        }
        if (!isCuetrackConfig(c)) {
          *err = "--config: unknown configuration '" + c +
                 "' (1.1 ... 1.4, 2.1 ... 2.5, best; ablations best-nolost, best-fixedsize, "
                 "best-nofastmotion, best-nocorrelation, 1.1-centrednegatives; best-filter)";
          return false;
        }
        configs.push_back(c);
      }
    } else if (a == "--runs" || a == "--peer-runs" || a == "--frames" || a == "--max-mem") {
      if (!value(&v)) return false;
      if (!parseCount(v, 1, 1000000, &n)) {
        *err = a + ": '" + v + "' is not a positive whole number";
        return false;
      }
      if (a == "--runs") o->runs = static_cast<int>(n);
      if (a == "--peer-runs") o->peerRuns = static_cast<int>(n);
      if (a == "--frames") o->maxFrames = static_cast<int>(n);
      if (a == "--max-mem") o->maxMemMiB = static_cast<size_t>(n);
    } else if (a == "--stride" || a == "--drop-frames") {
      if (!value(&v)) return false;
      const bool stride = a == "--stride";
      if (!parseCount(v, stride ? 1 : 0, stride ? 1000 : 95, &n)) {
        *err = a + ": '" + v +
               (stride ? "' is not a whole number from 1 to 1000"
                       : "' is not a whole percentage from 0 to 95");
        return false;
      }
      if (stride)
        o->stride = static_cast<int>(n);
      else
        o->dropPct = static_cast<int>(n);
    } else if (a == "--from" || a == "--to") {
      if (!value(&v)) return false;
      if (!parseCount(v, 0, 100000000, &n)) {
        *err = a + ": '" + v + "' is not a frame index (a whole number from 0)";
        return false;
      }
      (a == "--from" ? pending.fromIndex : pending.toIndex) = static_cast<int>(n);
    } else if (a == "--seed") {
      if (!value(&v)) return false;
      errno = 0;
      char* end = nullptr;
      const unsigned long long s = std::strtoull(v, &end, 10);
      if (errno != 0 || *end != '\0' || *v == '-' || *v == '\0') {
        *err = std::string("--seed: '") + v + "' is not a whole number";
        return false;
      }
      o->seed = s;
    } else if (a == "--json" || a == "--markdown" || a == "--csv" || a == "--plots" ||
               a == "--results" || a == "--overlay" || a == "--peer-cache" || a == "--video") {
      if (!value(&v)) return false;
      std::string& dst = a == "--json"         ? o->jsonPath
                         : a == "--markdown"   ? o->markdownPath
                         : a == "--csv"        ? o->csvDir
                         : a == "--plots"      ? o->plotDir
                         : a == "--overlay"    ? o->overlayDir
                         : a == "--peer-cache" ? o->peerCacheDir
                         : a == "--video"      ? o->videoDir
                                               : o->resultsDir;
      dst = v;
    } else if (a == "--paper") {
      if (!value(&v)) return false;
      if (std::strcmp(v, "table1") == 0) {
        o->paper = PaperReference::Table1;
      } else if (std::strcmp(v, "table3") == 0) {
        o->paper = PaperReference::Table3;
      } else {
        *err = std::string("--paper: '") + v + "' is not table1 or table3";
        return false;
      }
    } else if (a == "--skip-bad-frames") {
      o->skipBadFrames = true;
    } else if (a == "--reverse") {
      pending.reverse = true;
    } else if (a == "--rgb-only") {
      o->rgbOnly = true;
    } else if (a == "--quiet") {
      o->quiet = true;
    } else if (a.size() > 1 && a[0] == '-') {
      *err = "unknown option '" + a + "'";
      return false;
    } else {
      if (pending.fromIndex >= 0 && pending.toIndex >= 0 && pending.toIndex < pending.fromIndex) {
        *err = "--to " + std::to_string(pending.toIndex) + " lies before --from " +
               std::to_string(pending.fromIndex) + " (for " + a + ")";
        return false;
      }
      pending.spec = a;
      o->sequences.push_back(pending);
      pending = SequenceArg{};
    }
  }
  if (!pending.gtPath.empty()) {
    *err = "--gt " + pending.gtPath + " is not followed by a sequence";
    return false;
  }
  if (pending.fromIndex >= 0 || pending.toIndex >= 0 || pending.reverse) {
    *err = "--from / --to / --reverse are not followed by a sequence";
    return false;
  }
  if (o->sequences.empty()) {
    *err = "no sequence given";
    return false;
  }
  if (trackers.empty()) trackers.push_back("cuetrack");
  if (configs.empty()) configs.push_back("best");
  if (o->peerRuns < 0) o->peerRuns = o->runs;
  o->entries.clear();
  for (const std::string& t : trackers) {
    bool dup = false;
    for (const EntrySpec& e : o->entries) dup = dup || (e.tracker == t && t != "cuetrack");
    if (dup) continue;
    if (t == "cuetrack") {
      for (const std::string& c : configs) {
        bool have = false;
        for (const EntrySpec& e : o->entries) have = have || (e.tracker == t && e.config == c);
        if (!have) o->entries.push_back({t, c, o->runs});
      }
    } else {
      o->entries.push_back({t, "default", o->peerRuns});
    }
  }
  return true;
}

}  // namespace cuetrack::bench
