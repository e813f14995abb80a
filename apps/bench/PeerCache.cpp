#include "PeerCache.hpp"

#include <cerrno>
#include <cinttypes>
#include <cstdio>
#include <cstring>
#include <opencv2/core/version.hpp>

#include "Metrics.hpp"
#include "Outputs.hpp"

namespace cuetrack::bench {
namespace {

// 2: the figures carry the share of frames the centre distance covers (centerPct).
constexpr const char* kMagic = "cuetrack-peer-cache 2";

struct Fnv64 {
  uint64_t h = 1469598103934665603ull;
  void bytes(const void* p, size_t n) {
    const auto* b = static_cast<const unsigned char*>(p);
    for (size_t i = 0; i < n; ++i) h = (h ^ b[i]) * 1099511628211ull;
  }
  template <class T>
  void value(const T& v) {
    bytes(&v, sizeof v);
  }
  void text(const std::string& s) { bytes(s.data(), s.size() + 1); }
};

// Every frame's geometry, time and truth, and its pixels sampled on a sparse lattice
// (every 97th byte: a changed or re-encoded video changes far more than that).
uint64_t sequenceHash(const EntrySpec& spec, const Sequence& seq, uint64_t seed) {
  Fnv64 f;
  f.text(spec.tracker);
  f.text(CV_VERSION);
  f.text(kScoringRule);
  f.value(spec.runs);
  f.value(seed);
  f.text(seq.name);
  f.value(seq.frames.size());
  for (const CachedFrame& fr : seq.frames) {
    f.value(fr.index);
    f.value(fr.width);
    f.value(fr.height);
    f.value(fr.timeUs);
    f.value(fr.hasGroundTruth);
    f.value(fr.groundTruth.x);
    f.value(fr.groundTruth.y);
    f.value(fr.groundTruth.w);
    f.value(fr.groundTruth.h);
    const auto* px = reinterpret_cast<const unsigned char*>(fr.rgb.data());
    const size_t n = fr.rgb.size() * sizeof(Rgb8);
    for (size_t i = 0; i < n; i += 97) f.value(px[i]);
  }
  return f.h;
}

void writeArray(FILE* f, const char* key, const double* v, size_t n) {
  std::fprintf(f, "%s %zu", key, n);
  for (size_t i = 0; i < n; ++i) std::fprintf(f, " %.17g", v[i]);
  std::fprintf(f, "\n");
}

bool readArray(FILE* f, const char* key, double* v, size_t capacity, size_t* n) {
  char word[32];
  if (std::fscanf(f, "%31s %zu", word, n) != 2 || std::strcmp(word, key) != 0 || *n > capacity)
    return false;
  for (size_t i = 0; i < *n; ++i)
    if (std::fscanf(f, "%lf", &v[i]) != 1) return false;
  return true;
}

template <class Vec>
bool readVector(FILE* f, const char* key, Vec* out) {
  char word[32];
  size_t n = 0;
  if (std::fscanf(f, "%31s %zu", word, &n) != 2 || std::strcmp(word, key) != 0 || n > 10000000)
    return false;
  out->resize(n);
  for (size_t i = 0; i < n; ++i) {
    double v = 0.0;
    if (std::fscanf(f, "%lf", &v) != 1) return false;
    (*out)[i] = static_cast<typename Vec::value_type>(v);
  }
  return true;
}

}  // namespace

std::string peerCachePath(const std::string& dir, const EntrySpec& spec, const Sequence& seq,
                          uint64_t seed) {
  char hex[20];
  std::snprintf(hex, sizeof hex, "%016" PRIx64, sequenceHash(spec, seq, seed));
  return dir + "/" + spec.tracker + "/" + seq.name + "-" + hex + ".txt";
}

bool loadPeerResult(const std::string& path, SequenceResult* out) {
  FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) return false;
  SequenceResult r;
  char line[64] = {0};
  Figures& g = r.figures;
  size_t n = 0;
  std::vector<double> boxes;
  const bool ok = std::fgets(line, sizeof line, f) &&
                  std::strncmp(line, kMagic, std::strlen(kMagic)) == 0 &&
                  std::fscanf(f, "frames %d figures %lf %lf %lf %lf %lf %lf %lf %lf %lf %lf",
                              &g.frames, &g.overlap, &g.hit, &g.pascal, &g.centerPx, &g.centerPct,
                              &g.centerMm, &g.centerZMm, &g.msMedian, &g.msMean, &g.allocs) == 11 &&
                  readVector(f, "runs", &g.runOverlap) &&
                  readArray(f, "success", g.success, kSuccessSteps, &n) && n == kSuccessSteps &&
                  readArray(f, "precision", g.precision, kPrecisionSteps, &n) &&
                  n == kPrecisionSteps && readVector(f, "auc", &boxes) && boxes.size() == 2 &&
                  (g.auc = boxes[0], g.precision20 = boxes[1], true) &&
                  readVector(f, "frames", &r.frameIndex) &&
                  readVector(f, "overlap", &r.meanOverlap) && readVector(f, "boxes", &boxes) &&
                  boxes.size() % 4 == 0 && r.frameIndex.size() == r.meanOverlap.size();
  std::fclose(f);
  if (!ok) return false;
  for (size_t i = 0; i + 3 < boxes.size(); i += 4)
    r.firstRunBoxes.push_back(
        Box{float(boxes[i]), float(boxes[i + 1]), float(boxes[i + 2]), float(boxes[i + 3])});
  r.ran = true;
  r.name = out->name;
  r.skippedFrames = out->skippedFrames;  // the sequence's, not the peer's
  *out = std::move(r);
  return true;
}

bool savePeerResult(const std::string& path, const SequenceResult& result, std::string* err) {
  if (!result.ran) return true;  // a peer that cannot run says why each time
  const size_t slash = path.rfind('/');
  if (slash != std::string::npos && !makeDirs(path.substr(0, slash), err)) return false;
  const std::string tmp = path + ".tmp";
  FILE* f = std::fopen(tmp.c_str(), "wb");
  if (!f) {
    *err = tmp + ": cannot write: " + std::strerror(errno);
    return false;
  }
  const Figures& g = result.figures;
  std::fprintf(
      f, "%s\nframes %d figures %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
      kMagic, g.frames, g.overlap, g.hit, g.pascal, g.centerPx, g.centerPct, g.centerMm,
      g.centerZMm, g.msMedian, g.msMean, g.allocs);
  writeArray(f, "runs", g.runOverlap.data(), g.runOverlap.size());
  writeArray(f, "success", g.success, kSuccessSteps);
  writeArray(f, "precision", g.precision, kPrecisionSteps);
  const double single[2] = {g.auc, g.precision20};
  writeArray(f, "auc", single, 2);
  std::vector<double> frames(result.frameIndex.begin(), result.frameIndex.end());
  writeArray(f, "frames", frames.data(), frames.size());
  writeArray(f, "overlap", result.meanOverlap.data(), result.meanOverlap.size());
  std::vector<double> boxes;
  for (const Box& b : result.firstRunBoxes) boxes.insert(boxes.end(), {b.x, b.y, b.w, b.h});
  writeArray(f, "boxes", boxes.data(), boxes.size());
  const bool bad = std::ferror(f) != 0;
  if (std::fclose(f) != 0 || bad || std::rename(tmp.c_str(), path.c_str()) != 0) {
    *err = path + ": cannot write: " + std::strerror(errno);
    std::remove(tmp.c_str());
    return false;
  }
  return true;
}

}  // namespace cuetrack::bench
