// kinect::Pairer: buffer rotation and colour/depth pairing, without libfreenect.
#include <catch2/catch.hpp>

#include <thread>

#include "AllocCounter.hpp"
#include "cuetrack/drivers/KinectPairer.hpp"

using namespace cuetrack::kinect;

namespace {

constexpr uint32_t kFrameTicks = 2000000;  // 30 Hz at 60 MHz
constexpr uint32_t kUs = kTicksPerUs;

PairerConfig both(DropPolicy policy = DropPolicy::Latest) {
  PairerConfig c;
  c.policy = policy;
  return c;
}

// Feeds one colour and one depth frame `offsetTicks` apart.
void feedPair(Pairer& p, uint32_t colourTicks, int32_t depthOffsetTicks) {
  p.frameDone(Stream::Colour, colourTicks);
  p.frameDone(Stream::Depth, colourTicks + static_cast<uint32_t>(depthOffsetTicks));
}

}  // namespace

TEST_CASE("pairer pairs colour and depth frames within the tolerance", "[kinect][pairer]") {
  static Pairer p;
  p.reset(both());
  feedPair(p, 1000, 3000 * kUs);  // depth 3 ms after colour
  Taken t = p.take(0);
  REQUIRE(t.status == Taken::Status::Ok);
  CHECK(t.colour >= 0);
  CHECK(t.depth >= 0);
  p.release(t);
  // Depth first this time.
  p.frameDone(Stream::Depth, 1000 + kFrameTicks - 2000 * kUs);
  p.frameDone(Stream::Colour, 1000 + kFrameTicks);
  Taken t2 = p.take(0);
  REQUIRE(t2.status == Taken::Status::Ok);
  // Stamped with the colour frame's time; the two pairs are one frame apart.
  CHECK(t2.timeTicks - t.timeTicks == kFrameTicks);
  p.release(t2);
  const PairerCounters c = p.counters();
  CHECK(c.colourFrames == 2);
  CHECK(c.depthFrames == 2);
  CHECK(c.delivered == 2);
  CHECK(c.unpaired == 0);
  CHECK(c.dropped == 0);
}

TEST_CASE("pairer discards and counts frames without a partner", "[kinect][pairer]") {
  static Pairer p;
  PairerConfig cfg = both();
  cfg.toleranceTicks = 5000ull * kUs;
  p.reset(cfg);
  p.frameDone(Stream::Colour, 0);
  p.frameDone(Stream::Depth, 10000 * kUs);  // 10 ms later: too far, colour dropped
  CHECK(p.take(0).status == Taken::Status::Timeout);
  CHECK(p.counters().unpaired == 1);
  p.frameDone(Stream::Depth, 40000 * kUs);  // two depths in a row: the older goes
  CHECK(p.counters().unpaired == 2);
  p.frameDone(Stream::Colour, 41000 * kUs);  // pairs with the newest depth
  Taken t = p.take(0);
  REQUIRE(t.status == Taken::Status::Ok);
  CHECK(t.timeTicks % (1ull << 32) == 41000ull * kUs);
  p.release(t);
  CHECK(p.counters().unpaired == 2);
  CHECK(p.counters().delivered == 1);
}

TEST_CASE(
    "pairer Latest policy drops old pairs for a slow consumer and never hands out a buffer "
    "the library is writing",
    "[kinect][pairer]") {
  static Pairer p;
  p.reset(both(DropPolicy::Latest));
  for (int i = 0; i < 10; ++i) {
    const uint32_t t = static_cast<uint32_t>(i) * kFrameTicks;
    p.frameDone(Stream::Colour, t);
    const int nextDepth = p.frameDone(Stream::Depth, t + 100);
    CHECK(nextDepth == p.filling(Stream::Depth));
  }
  Taken t = p.take(0);
  REQUIRE(t.status == Taken::Status::Ok);
  CHECK(t.timeTicks % (1ull << 32) == 9ull * kFrameTicks);  // the newest
  // While the consumer holds the pair, more frames arrive: the library must never be
  // given the consumer's buffers.
  for (int i = 10; i < 20; ++i) {
    const uint32_t ts = static_cast<uint32_t>(i) * kFrameTicks;
    CHECK(p.frameDone(Stream::Colour, ts) != t.colour);
    CHECK(p.frameDone(Stream::Depth, ts + 100) != t.depth);
  }
  p.release(t);
  const PairerCounters c = p.counters();
  CHECK(c.delivered == 1);
  CHECK(c.dropped == 18);  // 20 pairs formed, 1 taken, 1 still ready
  Taken last = p.take(0);
  REQUIRE(last.status == Taken::Status::Ok);
  CHECK(last.timeTicks % (1ull << 32) == 19ull * kFrameTicks);
  p.release(last);
}

TEST_CASE("pairer Lossless policy delivers every pair in order to a slower consumer",
          "[kinect][pairer]") {
  static Pairer p;
  p.reset(both(DropPolicy::Lossless));
  constexpr int kPairs = 50;
  std::thread producer([] {
    for (int i = 0; i < kPairs; ++i) {
      const uint32_t t = static_cast<uint32_t>(i) * kFrameTicks;
      p.frameDone(Stream::Depth, t + 50);
      p.frameDone(Stream::Colour, t);
    }
    p.finish(EndKind::StreamEnded);
  });
  uint64_t expect = 0;
  int got = 0;
  bool ordered = true;
  for (;;) {
    Taken t = p.take(5000);
    if (t.status != Taken::Status::Ok) {
      CHECK(t.status == Taken::Status::End);
      CHECK(t.end == EndKind::StreamEnded);
      break;
    }
    if (got == 0) expect = t.timeTicks;
    ordered = ordered && t.timeTicks == expect;
    expect += kFrameTicks;
    ++got;
    p.release(t);
  }
  producer.join();
  CHECK(ordered);
  CHECK(got == kPairs);
  CHECK(p.counters().dropped == 0);
  CHECK(p.counters().unpaired == 0);
}

TEST_CASE("pairer: a stop request wakes a waiting producer and consumer", "[kinect][pairer]") {
  static Pairer p;
  p.reset(both(DropPolicy::Lossless));
  feedPair(p, 0, 100);  // Ready, nobody takes it
  std::thread producer([] {
    // Would wait for the consumer forever without the stop.
    p.frameDone(Stream::Colour, kFrameTicks);
    p.frameDone(Stream::Depth, kFrameTicks + 100);
  });
  p.requestStop();
  producer.join();
  Taken t = p.take(10000);
  CHECK(t.status == Taken::Status::End);
  CHECK(t.end == EndKind::Stopped);
}

TEST_CASE("pairer: a stop request ends a consumer already waiting for a pair", "[kinect][pairer]") {
  static Pairer p;
  p.reset(both(DropPolicy::Lossless));
  static Taken t;
  std::thread consumer([] { t = p.take(60000); });  // nothing will come
  // The stop must come while take() waits, or it would prove nothing.
  while (p.counters().consumerWaits == 0) std::this_thread::yield();
  p.requestStop();
  consumer.join();
  CHECK(t.status == Taken::Status::End);  // not Timeout after 60 s
  CHECK(t.end == EndKind::Stopped);
  CHECK(p.counters().consumerWaits == 1);
}

TEST_CASE("pairer: a finished stream delivers its last pair, then End; nothing gives Timeout",
          "[kinect][pairer]") {
  static Pairer p;
  p.reset(both());
  CHECK(p.take(0).status == Taken::Status::Timeout);
  feedPair(p, 0, 100);
  p.finish(EndKind::StreamEnded);
  Taken t = p.take(0);
  REQUIRE(t.status == Taken::Status::Ok);
  p.release(t);
  Taken e = p.take(0);
  CHECK(e.status == Taken::Status::End);
  CHECK(e.end == EndKind::StreamEnded);
}

TEST_CASE("pairer unwraps the 32-bit camera clock", "[kinect][pairer]") {
  static Pairer p;
  p.reset(both(DropPolicy::Lossless));
  const uint32_t nearWrap = 0xFFFFFFFFu - kFrameTicks / 2;
  feedPair(p, nearWrap, 100);
  Taken a = p.take(0);
  REQUIRE(a.status == Taken::Status::Ok);
  p.release(a);
  // Depth before the wrap, colour after: still one pair.
  p.frameDone(Stream::Depth, nearWrap + kFrameTicks - 200);
  p.frameDone(Stream::Colour, nearWrap + kFrameTicks);
  Taken b = p.take(0);
  REQUIRE(b.status == Taken::Status::Ok);
  CHECK(b.timeTicks - a.timeTicks == kFrameTicks);
  p.release(b);
  CHECK(p.counters().unpaired == 0);
}

TEST_CASE("pairer single-stream modes and the rate divisor", "[kinect][pairer]") {
  static Pairer p;
  PairerConfig cfg;
  cfg.useColour = false;  // depth only
  cfg.rateDivisor = 3;
  cfg.policy = DropPolicy::Lossless;
  p.reset(cfg);
  int delivered = 0;
  for (int i = 0; i < 9; ++i) {
    p.frameDone(Stream::Depth, static_cast<uint32_t>(i) * kFrameTicks);
    Taken t = p.take(0);
    if (t.status == Taken::Status::Ok) {
      CHECK(t.colour == -1);
      CHECK(t.depth >= 0);
      CHECK((t.timeTicks % (1ull << 32)) % (3ull * kFrameTicks) == 0);  // frames 0, 3, 6
      ++delivered;
      p.release(t);
    }
  }
  CHECK(delivered == 3);
  CHECK(p.counters().skippedByRate == 6);
  CHECK(p.counters().unpaired == 0);
}

TEST_CASE("pairer allocates nothing per frame after start", "[kinect][pairer][alloc]") {
  using cuetrack::test::AllocScope;
  {
    AllocScope control;
    int* leak = new int(7);  // positive control: the counter sees allocations
    CHECK(control.allocations() >= 1);
    delete leak;
  }
  static Pairer p;
  p.reset(both(DropPolicy::Latest));
  feedPair(p, 0, 100);  // warm-up (first lock use etc.)
  p.release(p.take(0));

  AllocScope scope;
  constexpr int kFrames = 300;
  int delivered = 0;
  for (int i = 1; i <= kFrames; ++i) {
    feedPair(p, static_cast<uint32_t>(i) * kFrameTicks, (i % 7) * 1000);
    if (i % 2 == 0) {  // a consumer at half rate: Latest drops, buffers rotate
      Taken t = p.take(0);
      if (t.status == Taken::Status::Ok) ++delivered;
      p.release(t);
    }
  }
  CHECK(delivered == kFrames / 2);
  CHECK(scope.allocations() == 0);
}
