#include "Json.hpp"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <nlohmann/json.hpp>

namespace cuetrack::bench {
namespace {

// Keys stay in the schema's order (nlohmann::json would sort them).
using Json = nlohmann::ordered_json;

// A figure as the schema gives it: rounded to `decimals` places (the double nearest
// printf's "%.Nf", which is what a reader of the earlier, printf-written files got), or
// null when it does not exist (NaN, an infinity, or `valid` false).
Json fixed(double v, int decimals, bool valid = true) {
  if (!valid || !std::isfinite(v)) return nullptr;
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
  return std::strtod(buf, nullptr);
}

template <class T>
Json fixedArray(const T* v, size_t n, int decimals, bool valid) {
  Json a = Json::array();
  for (size_t i = 0; valid && i < n; ++i) a.push_back(fixed(v[i], decimals));
  return a;
}

// The figures shared by a sequence and the average; `valid` false writes nulls.
void addFigures(Json& o, const Figures& f, bool valid) {
  o["frames"] = f.frames;
  o["overlap"] = fixed(f.overlap, 3, valid);
  o["hit"] = fixed(f.hit, 3, valid);
  o["pascal"] = fixed(f.pascal, 3, valid);
  o["center_px"] = fixed(f.centerPx, 3, valid);
  o["center_mm"] = fixed(f.centerMm, 1, valid);
  o["center_z_mm"] = fixed(f.centerZMm, 1, valid);
  o["ms_median"] = fixed(f.msMedian, 4, valid);
  o["ms_mean"] = fixed(f.msMean, 4, valid);
  o["allocs"] = fixed(f.allocs, 1, valid);
  o["auc"] = fixed(f.auc, 3, valid);
  o["precision20"] = fixed(f.precision20, 3, valid);
  o["overlap_spread"] = fixed(f.overlapSpread(), 3, valid);
  o["overlap_runs"] = fixedArray(f.runOverlap.data(), f.runOverlap.size(), 3, valid);
  o["success"] = fixedArray(f.success, kSuccessSteps, 4, valid);
  o["precision"] = fixedArray(f.precision, kPrecisionSteps, 4, valid);
}

Json entryJson(const EntryResult& e) {
  Json o;
  o["tracker"] = e.tracker;
  o["config"] = e.config;
  o["runs"] = e.runs;
  Json seqs = Json::array();
  for (const SequenceResult& s : e.sequences) {
    Json j;
    j["name"] = s.name;
    Figures f = s.figures;
    if (!s.ran) f.frames = 0;
    addFigures(j, f, s.ran);
    j["skipped_frames"] = s.skippedFrames;
    seqs.push_back(std::move(j));
  }
  o["sequences"] = std::move(seqs);
  Json avg;
  addFigures(avg, e.average(), e.sequencesRan() > 0);
  o["average"] = std::move(avg);
  if (!e.partial.empty()) o["partial"] = e.partial;  // interrupted: the figures so far
  return o;
}

}  // namespace

std::string toJson(const std::vector<EntryResult>& entries) {
  Json doc;
  if (entries.size() == 1) {
    doc = entryJson(entries.front());
  } else {
    doc = Json::array();
    for (const EntryResult& e : entries) doc.push_back(entryJson(e));
  }
  // A name that is not UTF-8 (a file name in another encoding) is written with U+FFFD
  // in place of the bad bytes instead of failing the output.
  return doc.dump(2, ' ', false, Json::error_handler_t::replace) + "\n";
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
