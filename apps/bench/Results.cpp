#include "Results.hpp"

namespace cuetrack::bench {

Figures EntryResult::average() const {
  std::vector<Figures> ran;
  for (const SequenceResult& s : sequences)
    if (s.ran) ran.push_back(s.figures);
  return averageFigures(ran);
}

int EntryResult::sequencesRan() const {
  int n = 0;
  for (const SequenceResult& s : sequences) n += s.ran ? 1 : 0;
  return n;
}

}  // namespace cuetrack::bench
