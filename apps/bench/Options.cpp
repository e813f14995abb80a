#include "Options.hpp"

#include "Peers.hpp"
#include "TrackerAdapters.hpp"
#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/Values.hpp"
#include "cuetrack/core/config/TrackerConfig.hpp"

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

// A whole number in [lo, hi], else the line `NAME: 'VALUE' IS_NOT`.
cli::Convert whole(const char* name, long lo, long hi, const char* isNot, long* out) {
  return [name, lo, hi, isNot, out](const std::string& v) {
    if (!cli::wholeNumber(v, lo, hi, out).empty())
      throw cli::BadCommandLine(std::string(name) + ": '" + cli::printable(v) + "' " + isNot);
    return std::string();
  };
}

const char* kAbout =
    "usage: cuetrack-bench [options] SEQUENCE...\n"
    "Runs trackers over recorded sequences with the protocol of Garcia et al. 2012:\n"
    "initialise at the first ground-truth box, track, score overlap / hit / PASCAL /\n"
    "centre distance, average over runs (seeds).";

const char* kFooter =
    "--tracker: cuetrack, opencv-kcf, opencv-csrt, opencv-mil, opencv-boosting,\n"
    "  opencv-medianflow, opencv-mosse, opencv-tld, or opencv-all (default cuetrack).\n"
    "--config: 1.1 ... 1.4, 2.1 ... 2.5, dcf, best (the default), or a preset with a\n"
    "  beyond-the-paper switch off: best-nolost, best-fixedsize, best-nofastmotion,\n"
    "  best-nocorrelation, best-noocclusion; or a paper preset with 2D negatives centred:\n"
    "  1.1-centrednegatives; best-template (the gray template as the correlation cue,\n"
    "  not the correlation filter); best-nofilterlead (2D: particles and classifier,\n"
    "  not the background-aware filter alone).\n"
    "SEQUENCE: a BoBoT video (NAME.avi, ground truth NAME.gt.txt beside it), any other\n"
    "  video (.mp4 .mkv .mov ...; NAME.gt.txt, or NAME.txt in OTB x,y,w,h form), an RGB-D\n"
    "  folder, an OTB or image folder, a fakenect recording (groundtruth.txt beside\n"
    "  INDEX.txt), or synth:<scene>; frames over 640x480 are scaled down to fit (scores in\n"
    "  the scaled pixels). A missing or broken sequence is reported and skipped.\n"
    "--gt, --from, --to and --reverse apply to the next SEQUENCE (list a file several\n"
    "  times with different --from / --to / --reverse for OTB-style temporal robustness).\n"
    "exit codes: 0 every sequence was sound and every output was written (a tracker\n"
    "  that cannot run on a sequence is reported and listed, not a failure); 1 a\n"
    "  sequence was missing or broken (unreadable, no ground truth, a first box outside\n"
    "  the image, frames changing size) or an output (stdout, --json, --markdown, --csv,\n"
    "  --plots, --results, --overlay, --video) failed: each is reported and the rest\n"
    "  goes on; 2 bad command line (an unknown scene, an output that would overwrite\n"
    "  an input or another output, too); 3 interrupted (SIGINT, SIGTERM, SIGHUP): the\n"
    "  report, --json and --markdown hold the figures so far, marked partial";

// What the declarations fill besides Options: the lists read in command-line order.
struct Lists {
  std::vector<std::string> sequences, trackers, configs, gts, froms, tos;
  long runs = -1, peerRuns = -1, frames = -1, maxMem = -1, stride = -1, dropPct = -1;
};

void declare(cli::Command& cmd, Options* o, Lists* l) {
  cmd.positionals("SEQUENCE", "a video, an RGB-D, OTB or fakenect folder, or synth:<scene>",
                  &l->sequences);
  cmd.list("--gt", "FILE", "ground truth for the next SEQUENCE", &l->gts);
  cmd.list("--tracker", "T[,T]", "trackers (below; repeatable)", &l->trackers);
  cmd.list("--config", "C[,C]", "cuetrack configurations (below; repeatable)", &l->configs);
  const char* positive = "is not a positive whole number";
  cmd.option("--runs", "N", "runs (seeds seed .. seed+N-1) per tracker (default 10)",
             whole("--runs", 1, 1000000, positive, &l->runs));
  cmd.option("--peer-runs", "N", "runs for the OpenCV peers (default: --runs)",
             whole("--peer-runs", 1, 1000000, positive, &l->peerRuns));
  cmd.option("--seed", "S", "first seed (default 1)", [o](const std::string& v) {
    if (!cli::seed(v, &o->seed).empty())
      throw cli::BadCommandLine("--seed: '" + cli::printable(v) + "' is not a whole number");
    return std::string();
  });
  cmd.option("--frames", "N", "use only the first N frames of each sequence",
             whole("--frames", 1, 1000000, positive, &l->frames));
  cmd.option("--stride", "K", "a K times slower camera: track every K-th frame after the first box",
             whole("--stride", 1, 1000, "is not a whole number from 1 to 1000", &l->stride));
  cmd.option("--drop-frames", "PCT",
             "a lossy link: drop PCT percent of the frames at random (the same ones for every "
             "tracker and run, from --seed)",
             whole("--drop-frames", 0, 95, "is not a whole percentage from 0 to 95", &l->dropPct));
  cmd.list("--from", "F", "for the next SEQUENCE: only its frames with index F on", &l->froms);
  cmd.list("--to", "T", "for the next SEQUENCE: only its frames with index up to T", &l->tos);
  cmd.app()
      .add_flag("--reverse",
                "for the next SEQUENCE: play it backwards, from its last ground-truth box")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
  cmd.flag("--skip-bad-frames", "let readers skip unreadable frames (counted) instead of failing",
           &o->skipBadFrames);
  cmd.flag("--rgb-only", "drop the depth of every sequence (best then runs 2D; 2.x fail)",
           &o->rgbOnly);
  cmd.option("--max-mem", "MIB", "memory for one decoded sequence (default 4096)",
             whole("--max-mem", 1, 1000000, positive, &l->maxMem));
  cmd.text("--json", "FILE", "figures in the schema of docs/bench-json.md", &o->jsonPath);
  cmd.text("--markdown", "FILE", "the tables as Markdown", &o->markdownPath);
  cmd.option(
      "--paper", "table1|table3", "put the paper's figures beside ours in the Markdown",
      [o](const std::string& v) {
        if (v == "table1") {
          o->paper = PaperReference::Table1;
        } else if (v == "table3") {
          o->paper = PaperReference::Table3;
        } else {
          throw cli::BadCommandLine("--paper: '" + cli::printable(v) + "' is not table1 or table3");
        }
        return std::string();
      });
  cmd.text("--csv", "DIR", "per-frame overlaps, DIR/<sequence>.overlap.csv", &o->csvDir);
  cmd.text("--plots", "DIR", "overlap-over-time plots, DIR/<sequence>.overlap.png", &o->plotDir);
  cmd.text("--results", "DIR",
           "BoBoT result files, DIR/<sequence>/<tracker>[-<config>].run<n>.txt (n = 1.. for "
           "seeds seed..)",
           &o->resultsDir);
  cmd.text("--overlay", "DIR", "frames with the boxes of run 1 drawn, DIR/<sequence>/NNNNNN.jpg",
           &o->overlayDir);
  cmd.text("--video", "DIR",
           "the same as one video per sequence, DIR/<sequence>.avi (Motion JPEG, 30 fps)",
           &o->videoDir);
  cmd.text("--peer-cache", "DIR", "keep and reuse the OpenCV peers' results (docs/bench-json.md)",
           &o->peerCacheDir);
  cmd.flag("--quiet", "no progress on stderr", &o->quiet);
}

}  // namespace

std::string usage() {
  cli::Command cmd("cuetrack-bench", kAbout, kFooter);
  Options o;
  Lists l;
  declare(cmd, &o, &l);
  return cmd.help();
}

namespace {

// --tracker's and --config's lists, each name checked.
bool readTrackers(const Lists& l, std::vector<std::string>* trackers,
                  std::vector<std::string>* configs, std::string* err) {
  for (const std::string& v : l.trackers) {
    for (const std::string& t : splitComma(v)) {
      if (t.empty()) {
        *err = "--tracker '" + v + "': an empty tracker name";
        return false;
      }
      if (t == "opencv-all") {
        for (int p = 0; p < kNumPeers; ++p) trackers->push_back(peerName(p));
      } else if (t == "cuetrack" || isPeerName(t)) {
        trackers->push_back(t);
      } else {
        *err = "--tracker: unknown tracker '" + t + "'";
        return false;
      }
    }
  }
  for (const std::string& v : l.configs) {
    for (const std::string& c : splitComma(v)) {
      if (c.empty()) {
        *err = "--config '" + v + "': an empty configuration name";
        return false;
      }
      if (!isCuetrackConfig(c)) {
        *err = "--config: unknown configuration '" + c +
               "' (1.1 ... 1.4, 2.1 ... 2.5, dcf, best; ablations best-nolost, best-fixedsize, "
               "best-nofastmotion, best-nocorrelation, 1.1-centrednegatives, best-template)";
        return false;
      }
      configs->push_back(c);
    }
  }
  return true;
}

// --gt, --from, --to and --reverse wait for their SEQUENCE: the command line's order.
bool readSequences(cli::Command& cmd, const Lists& l, Options* o, std::string* err) {
  SequenceArg pending;
  size_t next[5] = {0, 0, 0, 0, 0};  // gt, from, to, sequence, (reverse)
  for (const CLI::Option* opt : cmd.app().parse_order()) {
    const std::string name = opt->get_name();
    if (name == "--gt") {
      pending.gtPath = l.gts[next[0]++];
    } else if (name == "--from" || name == "--to") {
      const bool from = name == "--from";
      const std::string& v = from ? l.froms[next[1]++] : l.tos[next[2]++];
      long n = 0;
      if (!cli::wholeNumber(v, 0, 100000000, &n).empty()) {
        *err = name + ": '" + v + "' is not a frame index (a whole number from 0)";
        return false;
      }
      (from ? pending.fromIndex : pending.toIndex) = static_cast<int>(n);
    } else if (name == "--reverse") {
      pending.reverse = true;
    } else if (opt->get_positional()) {
      const std::string& a = l.sequences[next[3]++];
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
  return true;
}

// Every tracker once, cuetrack once per configuration, in the command line's order.
void makeEntries(const std::vector<std::string>& trackers, const std::vector<std::string>& configs,
                 Options* o) {
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
}

}  // namespace

bool parseOptions(int argc, const char* const* argv, Options* o, bool* help, std::string* err) {
  *help = false;
  cli::Command cmd("cuetrack-bench", kAbout, kFooter);
  Lists l;
  declare(cmd, o, &l);
  switch (cmd.check(argc, argv, err)) {
    case cli::Command::Parsed::Help:
      *help = true;
      return true;
    case cli::Command::Parsed::Error: {
      const std::string pointer = " (see --help)";  // main adds it
      if (err->size() > pointer.size() &&
          err->compare(err->size() - pointer.size(), pointer.size(), pointer) == 0)
        err->resize(err->size() - pointer.size());
      return false;
    }
    case cli::Command::Parsed::Run:
      break;
  }
  if (l.runs > 0) o->runs = static_cast<int>(l.runs);
  if (l.peerRuns > 0) o->peerRuns = static_cast<int>(l.peerRuns);
  if (l.frames > 0) o->maxFrames = static_cast<int>(l.frames);
  if (l.maxMem > 0) o->maxMemMiB = static_cast<size_t>(l.maxMem);
  if (l.stride > 0) o->stride = static_cast<int>(l.stride);
  if (l.dropPct >= 0) o->dropPct = static_cast<int>(l.dropPct);

  std::vector<std::string> trackers, configs;
  if (!readTrackers(l, &trackers, &configs, err) || !readSequences(cmd, l, o, err)) return false;
  if (trackers.empty()) trackers.push_back("cuetrack");
  if (configs.empty()) configs.push_back("best");
  if (o->peerRuns < 0) o->peerRuns = o->runs;
  makeEntries(trackers, configs, o);
  return true;
}

}  // namespace cuetrack::bench
