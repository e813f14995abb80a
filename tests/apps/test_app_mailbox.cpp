// LatestMailbox: the window's frames. The producer (the tracker's loop) never waits for
// the consumer, the newest item wins, and every item overwritten unseen is counted.
// The slow consumer is a thread held on a latch, not a sleep.
#include <catch2/catch.hpp>

#include <chrono>
#include <future>
#include <thread>

#include "LatestMailbox.hpp"

using cuetrack::app::LatestMailbox;
using namespace std::chrono_literals;

namespace {
struct Item {
  int value = -1;
  int writes = 0;  // how often this buffer was filled
};
}  // namespace

TEST_CASE("the newest item wins; items overwritten unseen are counted as dropped") {
  LatestMailbox<Item> box;
  CHECK(box.take(0ms) == nullptr);  // nothing yet
  box.push([](Item& it) { it.value = 1; });
  const Item* got = box.take(0ms);
  REQUIRE(got != nullptr);
  CHECK(got->value == 1);
  CHECK(box.take(0ms) == nullptr);  // taken once only
  box.push([](Item& it) { it.value = 2; });
  box.push([](Item& it) { it.value = 3; });
  box.push([](Item& it) { it.value = 4; });
  got = box.take(0ms);
  REQUIRE(got != nullptr);
  CHECK(got->value == 4);
  CHECK(box.dropped() == 2);  // 2 and 3
  CHECK(box.pushed() == 4);
}

TEST_CASE("a consumer stuck on its item never blocks the producer nor sees its item change") {
  LatestMailbox<Item> box;
  constexpr int kPushes = 1000;
  box.push([](Item& it) { it.value = 0; });

  std::promise<void> taken, release;
  std::shared_future<void> released = release.get_future().share();
  int heldValue = -1, heldAfter = -1, lastValue = -1;
  std::thread consumer([&] {
    const Item* held = box.take(10s);
    heldValue = held ? held->value : -2;
    taken.set_value();
    released.wait();  // "rendering" for as long as the test wants
    heldAfter = held ? held->value : -2;
    const Item* next = box.take(10s);
    lastValue = next ? next->value : -2;
  });
  taken.get_future().wait();

  // All pushes return while the consumer is still held (bounded wait: a deadlock guard).
  auto producer = std::async(std::launch::async, [&] {
    for (int i = 1; i <= kPushes; ++i)
      box.push([i](Item& it) {
        it.value = i;
        ++it.writes;
      });
  });
  const bool producerDone = producer.wait_for(60s) == std::future_status::ready;
  CHECK(producerDone);
  CHECK(box.pushed() == kPushes + 1);
  CHECK(box.dropped() == kPushes - 1);  // only the last of them survives

  release.set_value();
  consumer.join();
  if (!producerDone) producer.wait();
  CHECK(heldValue == 0);
  CHECK(heldAfter == 0);  // the producer never wrote into the consumer's buffer
  CHECK(lastValue == kPushes);
}

TEST_CASE("close() wakes a consumer waiting for an item") {
  LatestMailbox<Item> box;
  std::promise<const Item*> result;
  std::thread consumer([&] { result.set_value(box.take(3600s)); });
  box.close();
  auto f = result.get_future();
  REQUIRE(f.wait_for(60s) == std::future_status::ready);  // not the hour
  CHECK(f.get() == nullptr);
  consumer.join();
}
