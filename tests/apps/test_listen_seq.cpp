// cuetrack-listen's seq bookkeeping (SeqCounter): gaps are messages lost, a jump back is
// the device restarting, and a resumed run checks its first seq against the last one.
#include <catch2/catch.hpp>

#include "SeqCounter.hpp"

using cuetrack::listen::SeqCounter;

TEST_CASE("consecutive seq numbers lose nothing; a jump forward loses what it skips") {
  SeqCounter c;
  CHECK_FALSE(c.any());
  CHECK(c.see(5) == 0);  // the first one seen: nothing known before it
  CHECK(c.see(6) == 0);
  CHECK(c.see(10) == 3);  // 7, 8, 9
  CHECK(c.lost() == 3);
  CHECK(c.first() == 5);
  CHECK(c.last() == 10);
  CHECK(c.restarts() == 0);
}

TEST_CASE("a jump back is a device restart: the messages of its new run before it are lost") {
  SeqCounter c;
  c.see(100);
  CHECK(c.see(0) == 0);  // restarted and nothing missed
  CHECK(c.restarts() == 1);
  CHECK(c.see(1) == 0);
  CHECK(c.see(1) == 1);  // the same number again: another restart, 0 never arrived
  CHECK(c.restarts() == 2);
  CHECK(c.lost() == 1);
}

TEST_CASE("resuming after an earlier run's last seq counts the messages in between") {
  SeqCounter c;
  c.resumeAfter(4);
  CHECK(c.hasLast());
  CHECK_FALSE(c.any());
  CHECK(c.see(66) == 61);  // 5..65 went out while no listener ran
  CHECK(c.first() == 66);
  CHECK(c.lost() == 61);
  SeqCounter fresh;
  fresh.resumeAfter(4);
  CHECK(fresh.see(5) == 0);
  SeqCounter restarted;
  restarted.resumeAfter(400);
  CHECK(restarted.see(3) == 3);  // the device restarted meanwhile: 0, 1, 2 are lost
  CHECK(restarted.restarts() == 1);
}

TEST_CASE("seq wraps only after 2^32 messages; the largest numbers still count gaps") {
  SeqCounter c;
  c.see(0xfffffffdu);
  CHECK(c.see(0xffffffffu) == 1);
  CHECK(c.lost() == 1);
}
