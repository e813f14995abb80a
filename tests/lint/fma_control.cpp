// Positive control for check_no_fma.sh: compiled with contraction on purpose, so a*b + c
// becomes one fused instruction where the ISA has one.
namespace cuetrack {
float fusedControl(const float* a, const float* b, float c, int n) {
  for (int i = 0; i < n; ++i) c = a[i] * b[i] + c;
  return c;
}
}  // namespace cuetrack
