#include "Json.hpp"

#include <cerrno>
#include <cmath>
#include <cstring>

namespace cuetrack::bench {
namespace {

void appendString(std::string& out, const std::string& s) {
  out += '"';
  for (const char c : s) {
    switch (c) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (static_cast<unsigned char>(c) < 0x20) {
          char buf[8];
          std::snprintf(buf, sizeof buf, "\\u%04x", c);
          out += buf;
        } else {
          out += c;
        }
    }
  }
  out += '"';
}

void appendNumber(std::string& out, double v, int decimals, bool valid = true) {
  if (!valid || !std::isfinite(v)) {
    out += "null";
    return;
  }
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  out += buf;
}

// The figures shared by a sequence and the average; `valid` false writes nulls.
void appendFigures(std::string& out, const Figures& f, bool valid) {
  out += "\"frames\": ";
  appendNumber(out, f.frames, 0, true);
  out += ", \"overlap\": ";
  appendNumber(out, f.overlap, 3, valid);
  out += ", \"hit\": ";
  appendNumber(out, f.hit, 3, valid);
  out += ", \"pascal\": ";
  appendNumber(out, f.pascal, 3, valid);
  out += ", \"center_px\": ";
  appendNumber(out, f.centerPx, 3, valid);
  out += ", \"center_mm\": ";
  appendNumber(out, f.centerMm, 1, valid);
  out += ", \"center_z_mm\": ";
  appendNumber(out, f.centerZMm, 1, valid);
  out += ", \"ms_median\": ";
  appendNumber(out, f.msMedian, 4, valid);
  out += ", \"ms_mean\": ";
  appendNumber(out, f.msMean, 4, valid);
  out += ", \"allocs\": ";
  appendNumber(out, f.allocs, 1, valid);
  out += ", \"auc\": ";
  appendNumber(out, f.auc, 3, valid);
  out += ", \"precision20\": ";
  appendNumber(out, f.precision20, 3, valid);
  out += ", \"overlap_spread\": ";
  appendNumber(out, f.overlapSpread(), 3, valid);
  out += ", \"overlap_runs\": [";
  for (size_t k = 0; valid && k < f.runOverlap.size(); ++k) {
    if (k > 0) out += ", ";
    appendNumber(out, f.runOverlap[k], 3);
  }
  out += "], \"success\": [";
  for (int t = 0; valid && t < kSuccessSteps; ++t) {
    if (t > 0) out += ", ";
    appendNumber(out, f.success[t], 4);
  }
  out += "], \"precision\": [";
  for (int t = 0; valid && t < kPrecisionSteps; ++t) {
    if (t > 0) out += ", ";
    appendNumber(out, f.precision[t], 4);
  }
  out += "]";
}

void appendEntry(std::string& out, const EntryResult& e, const char* indent) {
  out += indent;
  out += "{\"tracker\": ";
  appendString(out, e.tracker);
  out += ", \"config\": ";
  appendString(out, e.config);
  out += ", \"runs\": ";
  appendNumber(out, e.runs, 0);
  out += ",\n";
  out += indent;
  out += " \"sequences\": [";
  for (size_t i = 0; i < e.sequences.size(); ++i) {
    const SequenceResult& s = e.sequences[i];
    out += i == 0 ? "\n" : ",\n";
    out += indent;
    out += "   {\"name\": ";
    appendString(out, s.name);
    out += ", ";
    Figures f = s.figures;
    if (!s.ran) f.frames = 0;
    appendFigures(out, f, s.ran);
    out += ", \"skipped_frames\": ";
    appendNumber(out, s.skippedFrames, 0);
    out += "}";
  }
  out += "],\n";
  out += indent;
  out += " \"average\": {";
  appendFigures(out, e.average(), e.sequencesRan() > 0);
  out += "}}";
}

}  // namespace

std::string toJson(const std::vector<EntryResult>& entries) {
  std::string out;
  if (entries.size() == 1) {
    appendEntry(out, entries.front(), "");
  } else {
    out += "[";
    for (size_t i = 0; i < entries.size(); ++i) {
      out += i == 0 ? "\n" : ",\n";
      appendEntry(out, entries[i], "  ");
    }
    out += "\n]";
  }
  out += "\n";
  return out;
}

bool writeJson(const char* path, const std::vector<EntryResult>& entries, std::string* err) {
  FILE* f = std::fopen(path, "wb");
  if (!f) {
    *err = std::string(path) + ": cannot write: " + std::strerror(errno);
    return false;
  }
  const std::string text = toJson(entries);
  const bool ok = std::fwrite(text.data(), 1, text.size(), f) == text.size();
  if (std::fclose(f) != 0 || !ok) {
    *err = std::string(path) + ": write failed: " + std::strerror(errno);
    return false;
  }
  return true;
}

}  // namespace cuetrack::bench
