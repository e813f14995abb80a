#include "Report.hpp"

#include <cmath>
#include <cstdarg>
#include <cstdio>
#include <limits>

#include "PaperFigures.hpp"

namespace cuetrack::bench {
namespace {

constexpr double kNan = std::numeric_limits<double>::quiet_NaN();
const char* const kStageNames[5] = {"features", "predict", "weigh", "learn", "total"};

void appendf(std::string& out, const char* fmt, ...) __attribute__((format(printf, 2, 3)));
void appendf(std::string& out, const char* fmt, ...) {
  char buf[512];
  va_list args;
  va_start(args, fmt);
  std::vsnprintf(buf, sizeof buf, fmt, args);
  va_end(args);
  out += buf;
}

std::string num(double v, int decimals) {
  if (std::isnan(v)) return "n/a";
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return buf;
}

const EntryResult* findTracker(const std::vector<EntryResult>& entries, const char* tracker) {
  for (const EntryResult& e : entries)
    if (e.tracker == tracker) return &e;
  return nullptr;
}

// What a table cell says for a sequence the entry did not run on.
const char* notRunCell(const SequenceResult& s) {
  return s.error.rfind("sequence failed", 0) == 0 ? "failed" : "cannot run";
}

// Too long a name loses its middle, not a slice's suffix (".from100.to300.rev"), which
// is what tells the columns of one file's runs apart.
std::string fit(const std::string& s, size_t width) {
  if (s.size() <= width) return s;
  size_t cut = s.size();
  for (const char* mark : {".from", ".to", ".rev"}) {
    const size_t at = s.rfind(mark);
    if (at != std::string::npos && at > 0 && at < cut) cut = at;
  }
  const size_t tail = s.size() - cut;
  if (tail == 0 || tail + 3 > width) return s.substr(0, width - 1) + "~";
  return s.substr(0, width - 1 - tail) + "~" + s.substr(cut);
}

// Two figures per sequence, then the averages: the paper's table layout, for each pair.
struct FigurePair {
  const char* textHead[2];
  const char* markdownHead[2];
  double Figures::*field[2];
  int decimals;
  bool textCpu, markdownCpu;  // a cpu [ms] column before the averages
};
const FigurePair kTable1{
    {"Over.", "Hit"}, {"Over.", "Hit"}, {&Figures::overlap, &Figures::hit}, 2, true, true};
const FigurePair kTable2{{"pascal", "dist."},
                         {"pascal", "dist. [px]"},
                         {&Figures::pascal, &Figures::centerPx},
                         2,
                         true,
                         false};
const FigurePair kCentreMm{{"3D", "z"},
                           {"3D err. [mm]", "z err. [mm]"},
                           {&Figures::centerMm, &Figures::centerZMm},
                           1,
                           false,
                           false};

void textTable(std::string& out, const std::vector<EntryResult>& entries, const FigurePair& c) {
  const auto& seqs = entries.front().sequences;
  appendf(out, "%-22s", "");
  for (const SequenceResult& s : seqs) appendf(out, " %-15s", fit(s.name, 15).c_str());
  appendf(out, c.textCpu ? " %-23s\n" : " %-15s\n", "Averages");
  appendf(out, "%-22s", "tracker");
  for (size_t i = 0; i < seqs.size(); ++i) appendf(out, " %7s %7s", c.textHead[0], c.textHead[1]);
  if (c.textCpu) appendf(out, " %7s", "cpu");
  appendf(out, " %7s %7s\n", c.textHead[0], c.textHead[1]);
  for (const EntryResult& e : entries) {
    appendf(out, "%-22s", fit(e.label(), 22).c_str());
    for (const SequenceResult& s : e.sequences) {
      if (!s.ran) {
        appendf(out, " %15s", notRunCell(s));
        continue;
      }
      appendf(out, " %7s %7s", num(s.figures.*c.field[0], c.decimals).c_str(),
              num(s.figures.*c.field[1], c.decimals).c_str());
    }
    const Figures a = e.average();
    const bool any = e.sequencesRan() > 0;
    if (c.textCpu) appendf(out, " %7s", any ? num(a.msMean, 2).c_str() : "-");
    appendf(out, " %7s %7s", any ? num(a.*c.field[0], c.decimals).c_str() : "-",
            any ? num(a.*c.field[1], c.decimals).c_str() : "-");
    if (any && e.sequencesRan() < static_cast<int>(e.sequences.size()))
      appendf(out, "  (over %d of %zu sequences)", e.sequencesRan(), e.sequences.size());
    out += "\n";
  }
}

void markdownTable(std::string& out, const std::vector<EntryResult>& entries, const FigurePair& c) {
  const auto& seqs = entries.front().sequences;
  out += "| | ";
  for (const SequenceResult& s : seqs)
    appendf(out, "%s %s | %s %s | ", s.name.c_str(), c.markdownHead[0], s.name.c_str(),
            c.markdownHead[1]);
  if (c.markdownCpu) out += "cpu [ms] | ";
  appendf(out, "Avg %s | Avg %s |\n|---|", c.markdownHead[0], c.markdownHead[1]);
  for (size_t i = 0; i < seqs.size(); ++i) out += "---:|---:|";
  out += c.markdownCpu ? "---:|---:|---:|\n" : "---:|---:|\n";
  for (const EntryResult& e : entries) {
    appendf(out, "| %s | ", e.label().c_str());
    for (const SequenceResult& s : e.sequences) {
      if (!s.ran)
        appendf(out, "%s | %s | ", notRunCell(s), notRunCell(s));
      else
        appendf(out, "%s | %s | ", num(s.figures.*c.field[0], c.decimals).c_str(),
                num(s.figures.*c.field[1], c.decimals).c_str());
    }
    const Figures a = e.average();
    if (e.sequencesRan() == 0) {
      out += c.markdownCpu ? "- | - | - |\n" : "- | - |\n";
      continue;
    }
    if (c.markdownCpu) appendf(out, "%s | ", num(a.msMean, 2).c_str());
    appendf(out, "%s | %s |\n", num(a.*c.field[0], c.decimals).c_str(),
            num(a.*c.field[1], c.decimals).c_str());
  }
}

// Whether any entry placed the target in 3D on a sequence that knows its 3D centre.
bool anyCenterMm(const std::vector<EntryResult>& entries) {
  for (const EntryResult& e : entries)
    for (const SequenceResult& s : e.sequences)
      if (s.ran && !std::isnan(s.figures.centerMm)) return true;
  return false;
}

// Failed sequences once each, then every tracker that could not run, with the reason.
std::string notRunList(const std::vector<EntryResult>& entries, const char* bullet) {
  std::string out;
  const auto& seqs = entries.front().sequences;
  for (size_t i = 0; i < seqs.size(); ++i)
    if (!seqs[i].ran && std::string(notRunCell(seqs[i])) == "failed")
      appendf(out, "%s%s: %s\n", bullet, seqs[i].name.c_str(), seqs[i].error.c_str());
  for (const EntryResult& e : entries)
    for (const SequenceResult& s : e.sequences)
      if (!s.ran && std::string(notRunCell(s)) != "failed")
        appendf(out, "%s%s on %s: %s\n", bullet, e.label().c_str(), s.name.c_str(),
                s.error.c_str());
  if (out.empty()) return out;
  return std::string(bullet[0] == '-' ? "\nNot run:\n\n" : "\nNot run:\n") + out;
}

}  // namespace

double speedRatio(const EntryResult& entry, const EntryResult& reference) {
  double a = 0.0, b = 0.0;
  for (size_t i = 0; i < entry.sequences.size() && i < reference.sequences.size(); ++i) {
    if (!entry.sequences[i].ran || !reference.sequences[i].ran) continue;
    a += entry.sequences[i].figures.msMean;
    b += reference.sequences[i].figures.msMean;
  }
  return b > 0.0 ? a / b : kNan;
}

// What dist. leaves out: per tracker, the share of frames it is averaged over.
std::string distCoverage(const std::vector<EntryResult>& entries, bool markdown) {
  std::string out = markdown ? "\n*dist.* averages only the frames where both the tracker's and "
                               "the true box exist; frames covered: "
                             : "dist. covers only frames where both boxes exist; frames covered: ";
  bool first = true;
  for (const EntryResult& e : entries) {
    if (e.sequencesRan() == 0) continue;
    appendf(out, "%s%s %s%%", first ? "" : ", ", e.label().c_str(),
            num(e.average().centerPct, 0).c_str());
    first = false;
  }
  out += "\n";
  return out;
}

std::string textReport(const std::vector<EntryResult>& entries) {
  std::string out;
  if (entries.empty()) return out;
  if (!entries.front().partial.empty()) out += "PARTIAL: " + entries.front().partial + "\n";
  if (entries.front().sequences.empty()) return out;
  bool anyRan = false;
  for (const EntryResult& e : entries) anyRan = anyRan || e.sequencesRan() > 0;
  if (!anyRan) return out + notRunList(entries, "  ").substr(1);  // no table of dashes
  out +=
      "Overlap and hit rate [%] (the paper's Table 1 layout); cpu = mean ms per frame, "
      "tracking only\n";
  textTable(out, entries, kTable1);
  out +=
      "\nPASCAL score [%] and mean centre distance [px] (the paper's Table 2 layout); dist. "
      "is over the frames where both boxes exist (lost frames left out: see below)\n";
  textTable(out, entries, kTable2);
  out += distCoverage(entries, false);
  if (anyCenterMm(entries)) {
    out +=
        "\n3D centre error and its depth part [mm], mean over frames where the target is "
        "visible and placed in 3D\n";
    textTable(out, entries, kCentreMm);
  }

  out +=
      "\nAverages with their seed-to-seed spread (sample s.d. of the per-seed averages), "
      "and OTB's one-pass figures: AUC of the success plot, precision at 20 px [%]\n";
  appendf(out, "%-22s %9s %9s %6s %9s %9s\n", "tracker", "overlap", "spread", "runs", "AUC",
          "prec@20");
  for (const EntryResult& e : entries) {
    if (e.sequencesRan() == 0) continue;
    const Figures a = e.average();
    appendf(out, "%-22s %9s %9s %6zu %9s %9s\n", fit(e.label(), 22).c_str(),
            num(a.overlap, 2).c_str(), num(a.overlapSpread(), 2).c_str(), a.runOverlap.size(),
            num(a.auc, 2).c_str(), num(a.precision20, 2).c_str());
  }

  const EntryResult* kcf = findTracker(entries, "opencv-kcf");
  const EntryResult* csrt = findTracker(entries, "opencv-csrt");
  out +=
      "\nSpeed, averaged over sequences: ms per frame (tracking only, decoding excluded), "
      "cuetrack per stage, heap allocations per run while tracking\n";
  appendf(out, "%-22s %9s %9s %9s %9s %9s %9s %11s %7s %7s\n", "tracker", "median", "mean",
          "features", "predict", "weigh", "learn", "allocs/run", "xKCF", "xCSRT");
  for (const EntryResult& e : entries) {
    if (e.sequencesRan() == 0) {
      appendf(out, "%-22s not run on any sequence\n", fit(e.label(), 22).c_str());
      continue;
    }
    const Figures a = e.average();
    appendf(out, "%-22s %9s %9s", fit(e.label(), 22).c_str(), num(a.msMedian, 3).c_str(),
            num(a.msMean, 3).c_str());
    for (int i = 0; i < 4; ++i)
      appendf(out, " %9s", a.hasStages ? num(a.stageMs[i], 3).c_str() : "-");
    appendf(out, " %11s %7s %7s\n", num(a.allocs, 0).c_str(),
            kcf ? num(speedRatio(e, *kcf), 2).c_str() : "-",
            csrt ? num(speedRatio(e, *csrt), 2).c_str() : "-");
  }
  out += notRunList(entries, "  ");
  return out;
}

namespace {

// The paper's Table 1 rows (tests 1.1-1.4) under ours, in italics, for the BoBoT sequences.
void paperTable1Rows(std::string& out, const std::vector<SequenceResult>& seqs) {
  char letter[8];
  const char* tests[4] = {"1.1", "1.2", "1.3", "1.4"};
  for (const char* t : tests) {
    appendf(out, "| *paper %s* | ", t);
    double sumO = 0, sumH = 0;
    int n = 0;
    bool all = true;
    for (const SequenceResult& s : seqs) {
      PaperCell c;
      if (paperTable1(bobotLetter(s.name.c_str(), letter, sizeof letter), t, &c)) {
        appendf(out, "*%.2f* | *%.2f* | ", c.overlap, c.hit);
        sumO += c.overlap;
        sumH += c.hit;
        ++n;
      } else {
        out += "n/a | n/a | ";
        all = false;
      }
    }
    const double cpu = paperTable1CpuMs(t);
    appendf(out, "*%s* | %s | %s |\n", num(cpu, 2).c_str(),
            all && n > 0 ? ("*" + num(sumO / n, 2) + "*").c_str() : "n/a",
            all && n > 0 ? ("*" + num(sumH / n, 2) + "*").c_str() : "n/a");
  }
}

}  // namespace

std::string markdownReport(const std::vector<EntryResult>& entries, PaperReference ref) {
  std::string out;
  if (entries.empty() || entries.front().sequences.empty()) return out;
  if (!entries.front().partial.empty()) out += "**Partial:** " + entries.front().partial + "\n\n";
  const auto& seqs = entries.front().sequences;

  markdownTable(out, entries, kTable1);
  if (ref == PaperReference::Table1) paperTable1Rows(out, seqs);

  out += "\n";
  markdownTable(out, entries, kTable2);
  out += distCoverage(entries, true);
  // The 3D centre's error, where the sequences know the target's 3D centre.
  if (anyCenterMm(entries)) {
    out += "\n";
    markdownTable(out, entries, kCentreMm);
  }

  out +=
      "\n| | Avg overlap | seed spread (s.d.) | runs | AUC (success) | precision at 20 px "
      "|\n|---|---:|---:|---:|---:|---:|\n";
  for (const EntryResult& e : entries) {
    if (e.sequencesRan() == 0) continue;
    const Figures a = e.average();
    appendf(out, "| %s | %s | %s | %zu | %s | %s |\n", e.label().c_str(), num(a.overlap, 2).c_str(),
            num(a.overlapSpread(), 2).c_str(), a.runOverlap.size(), num(a.auc, 2).c_str(),
            num(a.precision20, 2).c_str());
  }

  // Speed.
  const EntryResult* kcf = findTracker(entries, "opencv-kcf");
  const EntryResult* csrt = findTracker(entries, "opencv-csrt");
  out += "\n| | median [ms] | mean [ms] |";
  for (int i = 0; i < 4; ++i) appendf(out, " %s [ms] |", kStageNames[i]);
  out += " allocs / run | x KCF | x CSRT |\n|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|\n";
  for (const EntryResult& e : entries) {
    if (e.sequencesRan() == 0) {
      appendf(out, "| %s | not run | | | | | | | | |\n", e.label().c_str());
      continue;
    }
    const Figures a = e.average();
    appendf(out, "| %s | %s | %s |", e.label().c_str(), num(a.msMedian, 3).c_str(),
            num(a.msMean, 3).c_str());
    for (int i = 0; i < 4; ++i)
      appendf(out, " %s |", a.hasStages ? num(a.stageMs[i], 3).c_str() : "-");
    appendf(out, " %s | %s | %s |\n", num(a.allocs, 0).c_str(),
            kcf ? num(speedRatio(e, *kcf), 2).c_str() : "-",
            csrt ? num(speedRatio(e, *csrt), 2).c_str() : "-");
  }

  if (ref == PaperReference::Table3) {
    out +=
        "\nThe paper's Table 3 as printed (its own BoBoT-D Kinect sequences, which are not "
        "the sequences above; Xeon W3565):\n\n| | ";
    for (int i = 0; i < kPaperTable3Sequences; ++i)
      appendf(out, "%s Over. | %s Hit | ", paperTable3Sequence(i), paperTable3Sequence(i));
    out += "cpu [ms] | Avg Over. | Avg Hit |\n|---|";
    for (int i = 0; i < kPaperTable3Sequences; ++i) out += "---:|---:|";
    out += "---:|---:|---:|\n";
    const char* tests[5] = {"2.1", "2.2", "2.3", "2.4", "2.5"};
    for (const char* t : tests) {
      appendf(out, "| paper %s | ", t);
      for (int i = 0; i < kPaperTable3Sequences; ++i) {
        PaperCell c{};
        paperTable3(i, t, &c);
        appendf(out, "%.2f | %.2f | ", c.overlap, c.hit);
      }
      PaperCell avg{};
      paperTable3Average(t, &avg);
      appendf(out, "%.2f | %.2f | %.2f |\n", paperTable3CpuMs(t), avg.overlap, avg.hit);
    }
  }

  out += notRunList(entries, "- ");
  return out;
}

}  // namespace cuetrack::bench
