// The Kinect pairer on one thread: any interleaving of colour and depth frames (with
// their 32-bit camera times, wraps included), takes and releases, and an end. Buffer
// indices stay in range, the consumer never gets a buffer the library is filling, pair
// times never go back, and the counters add up. (Lossless would wait for the consumer
// in frameDone, which one thread cannot be: Latest only.)
#include <cstddef>
#include <cstdint>

#include "cuetrack/drivers/KinectPairer.hpp"

using namespace cuetrack::kinect;

namespace {
bool valid(int b) {
  return b >= 0 && b < kBuffersPerStream;
}
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size < 2) return 0;
  static Pairer p;
  PairerConfig cfg;
  cfg.useColour = (data[0] & 1) != 0 || (data[0] & 2) == 0;  // never neither
  cfg.useDepth = (data[0] & 2) != 0;
  cfg.rateDivisor = 1 + (data[1] & 3);
  cfg.toleranceTicks = static_cast<uint64_t>(1 + (data[1] >> 2)) * 1000u * kTicksPerUs;
  p.reset(cfg);
  uint32_t ticks[2] = {0, 0};
  Taken held;
  bool holding = false, haveTime = false, ended = false;
  uint64_t lastTime = 0;
  for (size_t i = 2; i + 2 < size; i += 3) {
    const uint8_t op = data[i] & 3;
    const uint32_t step = static_cast<uint32_t>(data[i + 1] | (data[i + 2] << 8)) * 997u;
    if (op <= 1 && !ended) {
      const Stream s = op == 0 ? Stream::Colour : Stream::Depth;
      if ((s == Stream::Colour && !cfg.useColour) || (s == Stream::Depth && !cfg.useDepth))
        continue;
      const int k = static_cast<int>(s);
      ticks[k] += step;  // wraps like the camera's counter
      const int next = p.frameDone(s, ticks[k]);
      if (!valid(next)) __builtin_trap();
      if (holding && ((s == Stream::Colour && next == held.colour) ||
                      (s == Stream::Depth && next == held.depth)))
        __builtin_trap();  // the library would overwrite what the consumer reads
    } else if (op == 2) {
      if (holding) {
        p.release(held);
        holding = false;
      }
      const Taken t = p.take(0);
      if (t.status == Taken::Status::Ok) {
        if (cfg.useColour && !valid(t.colour)) __builtin_trap();
        if (cfg.useDepth && !valid(t.depth)) __builtin_trap();
        if (cfg.useColour && t.colour == p.filling(Stream::Colour)) __builtin_trap();
        if (cfg.useDepth && t.depth == p.filling(Stream::Depth)) __builtin_trap();
        if (haveTime && t.timeTicks < lastTime) __builtin_trap();  // unwrapped: forwards
        lastTime = t.timeTicks;
        haveTime = true;
        held = t;
        holding = true;
      }
    } else if (op == 3 && (data[i + 1] & 0x0f) == 0 && !ended) {
      p.finish(EndKind::StreamEnded);
      ended = true;
    }
  }
  if (holding) p.release(held);
  const PairerCounters c = p.counters();
  if (c.delivered > c.colourFrames + c.depthFrames) __builtin_trap();
  return 0;
}
