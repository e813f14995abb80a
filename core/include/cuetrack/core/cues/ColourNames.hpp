// The colour-names table (van de Weijer, Schmid, Verbeek, Larlus, "Learning Color Names
// for Real-World Applications", 2009), as the hand-crafted correlation-filter trackers
// (CN, ECO-HC, STRCF) use it: for each RGB colour quantised to 32 levels a channel, 10
// numbers that say how much it looks like each of the eleven basic colour names,
// projected to 10 dimensions. A compile-time constant (core/src/ColourNamesTable.cpp,
// written by scripts/colour_names_table.py), int8 in steps of 1/128: 320 KiB instead
// of 1.25 MiB, at most 0.004 off, and the same bits on every ISA. The tests check its
// sha256 and, where ../shared is present, that it is the shared table quantised.
#pragma once

#include <cstdint>

namespace cuetrack::colourNames {

inline constexpr int kNames = 10;
inline constexpr int kRows = 32 * 32 * 32;
inline constexpr float kStep = 1.f / 128.f;  // a table entry times this is the value

extern const int8_t kTable[kRows][kNames];
extern const char kSourceSha256[];  // the float32 table it was made from
extern const char kTableSha256[];   // kTable's bytes, row by row

// The row of colour (r, g, b), each 0..255 (the table's own indexing).
inline int rowOf(int r, int g, int b) {
  return (r >> 3) + 32 * (g >> 3) + 1024 * (b >> 3);
}

}  // namespace cuetrack::colourNames
