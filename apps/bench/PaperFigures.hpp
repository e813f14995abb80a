// The paper's own figures (García et al. 2012), to print beside ours. Only values
// legible in /work/shared/paper/adaptive-multicue-3d-tracking.txt are here; a
// missing one is NaN. Table 1: BoBoT (RGB, 2D state) tests 1.1-1.4; Table 3:
// BoBoT-D (RGB-D) tests 2.1-2.5. Measured on a Xeon W3565 @ 3.2 GHz.
#pragma once

namespace cuetrack::bench {

struct PaperCell {
  double overlap;  // [%]
  double hit;      // [%]
};

// Table 1 for BoBoT sequence `letter` ("A" ... "L", "Ia", "Jb") and test "1.1".."1.4";
// false when the paper has no legible figure for it.
bool paperTable1(const char* letter, const char* test, PaperCell* out);
// Table 1's cpu column [ms per frame]; NaN when not legible.
double paperTable1CpuMs(const char* test);

// Table 3: sequences in the paper's order.
inline constexpr int kPaperTable3Sequences = 5;
const char* paperTable3Sequence(int i);  // "1 (Milk)" ...
bool paperTable3(int sequence, const char* test, PaperCell* out);
double paperTable3CpuMs(const char* test);
bool paperTable3Average(const char* test, PaperCell* out);

// "Vid_C_juice" -> "C"; empty when the name is not a BoBoT video name.
const char* bobotLetter(const char* sequenceName, char* buf, int bufLen);

}  // namespace cuetrack::bench
