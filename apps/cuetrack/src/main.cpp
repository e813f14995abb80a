// cuetrack: the on-board tracker. All wiring is in App.cpp; this file only picks
// the real tracker and gives it static storage (it is MiBs).
#include "App.hpp"
#include "CoreTracker.hpp"

int main(int argc, char** argv) {
  static cuetrack::Tracker tracker;
  static cuetrack::app::CoreTracker port(tracker);
  return cuetrack::app::runCuetrack(argc, argv, port);
}
