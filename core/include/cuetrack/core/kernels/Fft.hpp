// A fixed-size 2D FFT for the correlation filter (CorrelationFilter.hpp): kFftSide x
// kFftSide complex values, split into real and imaginary planes, transformed in place.
// Radix-2, decimation in time, twiddles written out as literals and one operation order,
// built with -ffp-contract=off: the same bits on x86-64, aarch64 and armhf, which a
// library with run-time plans and its own SIMD paths (FFTW, kissfft) would not promise.
// The cost is small beside the features: 32 x 32 is 64 transforms of 32 points, about
// 10^4 flops each way.
#pragma once

namespace cuetrack {

inline constexpr int kFftLog2 = 5;
inline constexpr int kFftSide = 1 << kFftLog2;  // 32
inline constexpr int kFftSize = kFftSide * kFftSide;

namespace fft {

// One transform of kFftSide points at stride `step` (a row: 1; a column: kFftSide).
// inverse: e^{+2 pi i k n / N}, unscaled.
void transform1d(float* re, float* im, int step, bool inverse);

// The 2D transform of re + i im in place: columns, a transpose, columns again. The
// spectrum is left transposed (frequency (ky, kx) at [kx][ky]), which saves transposing
// back: products of spectra do not mind, and inverse2d takes a transposed spectrum back
// to the plane as it was. inverse2d is scaled by 1 / kFftSize, so inverse2d(forward2d(x))
// == x up to rounding.
void forward2d(float* re, float* im);
void inverse2d(float* re, float* im);

// The transforms of two real planes a and b at once (a + i b, then split by the
// symmetry X[-k] = conj X[k] of a real plane's transform): a's transform into (ar, ai),
// b's into (br, bi). a and b are read; ar..bi are written (none may alias a or b).
void forwardRealPair(const float* a, const float* b, float* ar, float* ai, float* br, float* bi);

// cos(2 pi k / kFftSide) for k in [0, kFftSide), from the same table (for windows).
float cosTurn(int k);

}  // namespace fft
}  // namespace cuetrack
