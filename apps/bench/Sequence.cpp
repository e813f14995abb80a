#include "Sequence.hpp"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "cuetrack/platform/linux/Signals.hpp"

namespace cuetrack::bench {

Frame CachedFrame::frame() const {
  Frame f;
  f.rgb = RgbView{rgb.data(), width, height, width};
  if (!depthMm.empty()) f.depthMm = DepthView{depthMm.data(), width, height, width};
  f.timeUs = timeUs;
  f.intrinsics = intrinsics;
  return f;
}

bool loadSequence(FrameSource& source, int maxFrames, size_t maxBytes, Sequence* seq,
                  std::string* err) {
  seq->name = source.name();
  seq->frames.clear();
  seq->bytes = 0;
  // The slot is 1.5 MiB: one for the whole process, reused.
  static FrameSlot slot;
  for (;;) {
    if (maxFrames > 0 && static_cast<int>(seq->frames.size()) >= maxFrames) break;
    if (platform::stopRequested()) {
      *err = seq->name + ": interrupted while decoding";
      return false;
    }
    slot.hasTruthMm = false;  // only sources that know the 3D truth set it
    const ReadStatus st = source.next(slot);
    if (st == ReadStatus::End) break;
    if (st == ReadStatus::Error) {
      *err = source.error();
      if (err->empty()) *err = seq->name + ": read error";
      return false;
    }
    CachedFrame f;
    f.index = slot.index;
    f.width = slot.rgb.width();
    f.height = slot.rgb.height();
    const size_t px = static_cast<size_t>(f.width) * static_cast<size_t>(f.height);
    f.rgb.assign(slot.rgb.data(), slot.rgb.data() + px);
    if (slot.hasDepth && slot.depthMm.width() == f.width && slot.depthMm.height() == f.height)
      f.depthMm.assign(slot.depthMm.data(), slot.depthMm.data() + px);
    f.timeUs = slot.timeUs;
    f.intrinsics = slot.intrinsics;
    f.hasGroundTruth = slot.hasGroundTruth;
    f.groundTruth = slot.groundTruth;
    f.hasTruthMm = slot.hasTruthMm;
    for (int a = 0; a < 3; ++a) f.truthCentreMm[a] = slot.truthCentreMm[a];
    if (px > 0) {
      const cv::Mat rgbMat(f.height, f.width, CV_8UC3, f.rgb.data());
      cv::cvtColor(rgbMat, f.bgr, cv::COLOR_RGB2BGR);
    }
    seq->bytes += px * (2 * sizeof(Rgb8)) + f.depthMm.size() * sizeof(uint16_t);
    seq->frames.push_back(std::move(f));
    if (seq->bytes > maxBytes) {
      *err = seq->name + ": more than " + std::to_string(maxBytes >> 20) +
             " MiB of decoded frames; cut it with --frames N";
      return false;
    }
  }
  seq->skippedFrames = source.skippedFrames();
  if (seq->frames.empty()) {
    *err = seq->name + ": no frames";
    return false;
  }
  return true;
}

void thinSequence(Sequence* seq, int stride, int dropPct, uint64_t seed) {
  if (stride <= 1 && dropPct <= 0) return;
  size_t initAt = seq->frames.size();
  for (size_t i = 0; i < seq->frames.size(); ++i)
    if (seq->frames[i].hasGroundTruth && !seq->frames[i].groundTruth.empty()) {
      initAt = i;
      break;
    }
  if (initAt == seq->frames.size()) return;  // runEntry reports it
  std::vector<CachedFrame> kept;
  kept.reserve(seq->frames.size());
  for (size_t i = 0; i < seq->frames.size(); ++i) {
    bool keep = i <= initAt;
    if (!keep && (i - initAt) % static_cast<size_t>(stride < 1 ? 1 : stride) == 0) {
      // splitmix64 of (seed, frame index): a fair draw per frame, reproducible.
      uint64_t h = seed * 0x9E3779B97F4A7C15ull + static_cast<uint64_t>(seq->frames[i].index);
      h = (h ^ (h >> 30)) * 0xBF58476D1CE4E5B9ull;
      h = (h ^ (h >> 27)) * 0x94D049BB133111EBull;
      h ^= h >> 31;
      keep = static_cast<int>(h % 100) >= dropPct;
    }
    if (keep)
      kept.push_back(std::move(seq->frames[i]));
    else
      ++seq->droppedFrames;
  }
  seq->frames = std::move(kept);
}

bool sliceSequence(Sequence* seq, int fromIndex, int toIndex, bool reverse, std::string* err) {
  if (fromIndex < 0 && toIndex < 0 && !reverse) return true;
  const size_t before = seq->frames.size();
  std::vector<CachedFrame> kept;
  kept.reserve(before);
  for (CachedFrame& f : seq->frames)
    if ((fromIndex < 0 || f.index >= fromIndex) && (toIndex < 0 || f.index <= toIndex))
      kept.push_back(std::move(f));
  std::string suffix;
  if (fromIndex >= 0) suffix += ".from" + std::to_string(fromIndex);
  if (toIndex >= 0) suffix += ".to" + std::to_string(toIndex);
  if (reverse) suffix += ".rev";
  const std::string base = seq->name;
  seq->name += suffix;  // also when it fails: the tables then name the slice that failed
  if (kept.empty()) {
    *err = base + ": no frame has an index in " +
           (fromIndex < 0 ? std::string("0") : std::to_string(fromIndex)) + ".." +
           (toIndex < 0 ? std::string("end") : std::to_string(toIndex)) + " (of " +
           std::to_string(before) + " frames)";
    return false;
  }
  if (reverse) {
    uint64_t tMin = kept.front().timeUs, tMax = kept.front().timeUs;
    for (const CachedFrame& f : kept) {
      tMin = std::min(tMin, f.timeUs);
      tMax = std::max(tMax, f.timeUs);
    }
    std::reverse(kept.begin(), kept.end());
    for (CachedFrame& f : kept) f.timeUs = tMin + (tMax - f.timeUs);
  }
  seq->frames = std::move(kept);
  return true;
}

}  // namespace cuetrack::bench
