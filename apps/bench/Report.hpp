// Human-readable reports: the stdout tables in the paper's layouts (Table 1:
// overlap / hit per sequence, cpu and averages; Table 2: PASCAL / centre distance),
// a speed table with per-stage times, allocations and ratios to KCF and CSRT from
// the same run, and the same as Markdown for docs/benchmarks.md.
#pragma once

#include <string>
#include <vector>

#include "Results.hpp"

namespace cuetrack::bench {

enum class PaperReference {
  None,
  Table1,  // BoBoT: the paper's rows for the sequences whose names give a BoBoT letter
  Table3,  // BoBoT-D: the paper's table as printed (its sequences are not ours)
};

std::string textReport(const std::vector<EntryResult>& entries);
std::string markdownReport(const std::vector<EntryResult>& entries, PaperReference ref);

// Ratio of `entry`'s mean ms per frame to `reference`'s over the sequences both ran
// on; NaN when there is none.
double speedRatio(const EntryResult& entry, const EntryResult& reference);

}  // namespace cuetrack::bench
