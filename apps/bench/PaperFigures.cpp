#include "PaperFigures.hpp"

#include <cmath>
#include <cstring>
#include <limits>

namespace cuetrack::bench {
namespace {

constexpr double kNa = std::numeric_limits<double>::quiet_NaN();

struct Table1Row {
  const char* letter;
  PaperCell cells[4];  // tests 1.1 .. 1.4
};
// Rows A-H as printed in Table 1 (H for 1.4 is not legible in our copy).
const Table1Row kTable1[] = {
    {"A", {{76.29, 99.95}, {75.06, 99.98}, {76.78, 99.8}, {62.09, 94.0}}},
    {"B", {{80.55, 100.0}, {80.22, 100.0}, {81.59, 100.0}, {81.71, 100.0}}},
    {"C", {{92.33, 100.0}, {91.85, 100.0}, {92.95, 100.0}, {93.20, 100.0}}},
    {"D", {{81.07, 100.0}, {80.48, 100.0}, {80.48, 100.0}, {79.94, 100.0}}},
    {"E", {{87.26, 100.0}, {87.08, 100.0}, {87.03, 100.0}, {87.26, 100.0}}},
    {"F", {{65.19, 91.85}, {65.47, 91.74}, {65.40, 91.83}, {65.00, 91.78}}},
    {"G", {{73.68, 100.0}, {72.60, 100.0}, {72.64, 100.0}, {76.01, 100.0}}},
    {"H", {{97.25, 100.0}, {96.52, 100.0}, {96.12, 100.0}, {kNa, kNa}}},
};
const double kTable1Cpu[4] = {30.89, 31.13, 37.80, kNa};

const char* const kTable3Names[kPaperTable3Sequences] = {"1 (Milk)", "2 (Ball)", "3 (Tank)",
                                                         "4 (Person)", "5 (Box)"};
struct Table3Row {
  PaperCell cells[kPaperTable3Sequences];
  double cpuMs;
  PaperCell average;
};
const Table3Row kTable3[5] = {
    {{{73.47, 96.77}, {69.80, 96.91}, {55.33, 94.09}, {70.67, 95.32}, {73.10, 99.81}},
     30.69,
     {68.47, 96.58}},
    {{{74.61, 95.29}, {66.39, 95.31}, {55.01, 94.27}, {70.55, 95.31}, {75.20, 100.00}},
     31.4,
     {68.35, 96.04}},
    {{{73.21, 96.39}, {68.63, 96.94}, {54.46, 93.80}, {71.92, 95.17}, {75.57, 100.00}},
     33.52,
     {68.76, 96.46}},
    {{{73.45, 94.48}, {55.60, 83.68}, {32.23, 40.72}, {70.72, 95.92}, {70.88, 99.76}},
     36.97,
     {60.58, 82.91}},
    {{{69.01, 89.14}, {14.08, 19.07}, {28.92, 32.30}, {67.07, 91.70}, {47.42, 70.66}},
     27.90,
     {45.3, 60.57}},
};

// "1.1" -> 0 ... "1.4" -> 3 for major 1; -1 otherwise.
int testIndex(const char* test, char major, int count) {
  if (!test || std::strlen(test) != 3 || test[0] != major || test[1] != '.') return -1;
  const int i = test[2] - '1';
  return i >= 0 && i < count ? i : -1;
}

}  // namespace

bool paperTable1(const char* letter, const char* test, PaperCell* out) {
  const int t = testIndex(test, '1', 4);
  if (t < 0 || !letter) return false;
  for (const Table1Row& r : kTable1) {
    if (std::strcmp(r.letter, letter) == 0) {
      if (std::isnan(r.cells[t].overlap)) return false;
      *out = r.cells[t];
      return true;
    }
  }
  return false;
}

double paperTable1CpuMs(const char* test) {
  const int t = testIndex(test, '1', 4);
  return t < 0 ? kNa : kTable1Cpu[t];
}

const char* paperTable3Sequence(int i) {
  return i >= 0 && i < kPaperTable3Sequences ? kTable3Names[i] : "";
}

bool paperTable3(int sequence, const char* test, PaperCell* out) {
  const int t = testIndex(test, '2', 5);
  if (t < 0 || sequence < 0 || sequence >= kPaperTable3Sequences) return false;
  *out = kTable3[t].cells[sequence];
  return true;
}

double paperTable3CpuMs(const char* test) {
  const int t = testIndex(test, '2', 5);
  return t < 0 ? kNa : kTable3[t].cpuMs;
}

bool paperTable3Average(const char* test, PaperCell* out) {
  const int t = testIndex(test, '2', 5);
  if (t < 0) return false;
  *out = kTable3[t].average;
  return true;
}

const char* bobotLetter(const char* name, char* buf, int bufLen) {
  buf[0] = '\0';
  if (std::strncmp(name, "Vid_", 4) != 0) return buf;
  const char* p = name + 4;
  int n = 0;
  while (p[n] && p[n] != '_' && n + 1 < bufLen) {
    buf[n] = p[n];
    ++n;
  }
  buf[n] = '\0';
  return buf;
}

}  // namespace cuetrack::bench
