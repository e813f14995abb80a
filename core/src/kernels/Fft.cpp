#include "cuetrack/core/kernels/Fft.hpp"

namespace cuetrack::fft {

namespace {
// cos and sin of 2 pi k / 32, k = 0..15 (double-precision values rounded to float).
constexpr float kCos[kFftSide / 2] = {1.000000000f,  0.980785280f,  0.923879533f,  0.831469612f,
                                      0.707106781f,  0.555570233f,  0.382683432f,  0.195090322f,
                                      0.000000000f,  -0.195090322f, -0.382683432f, -0.555570233f,
                                      -0.707106781f, -0.831469612f, -0.923879533f, -0.980785280f};
constexpr float kSin[kFftSide / 2] = {0.000000000f, 0.195090322f, 0.382683432f, 0.555570233f,
                                      0.707106781f, 0.831469612f, 0.923879533f, 0.980785280f,
                                      1.000000000f, 0.980785280f, 0.923879533f, 0.831469612f,
                                      0.707106781f, 0.555570233f, 0.382683432f, 0.195090322f};
static_assert(kFftSide == 32, "the twiddle tables are written for 32 points");

constexpr int reverseBits(int v) {
  int r = 0;
  for (int b = 0; b < kFftLog2; ++b) r |= ((v >> b) & 1) << (kFftLog2 - 1 - b);
  return r;
}
}  // namespace

void transform1d(float* re, float* im, int step, bool inverse) {
  for (int i = 0; i < kFftSide; ++i) {
    const int j = reverseBits(i);
    if (j <= i) continue;
    float t = re[i * step];
    re[i * step] = re[j * step];
    re[j * step] = t;
    t = im[i * step];
    im[i * step] = im[j * step];
    im[j * step] = t;
  }
  const float sign = inverse ? 1.f : -1.f;
  for (int half = 1; half < kFftSide; half *= 2) {
    const int twStep = kFftSide / (2 * half);
    for (int k = 0; k < half; ++k) {
      const float wr = kCos[k * twStep];
      const float wi = sign * kSin[k * twStep];
      for (int s = k; s < kFftSide; s += 2 * half) {
        float* ar = re + s * step;
        float* ai = im + s * step;
        float* br = re + (s + half) * step;
        float* bi = im + (s + half) * step;
        const float tr = wr * *br - wi * *bi;
        const float ti = wr * *bi + wi * *br;
        *br = *ar - tr;
        *bi = *ai - ti;
        *ar = *ar + tr;
        *ai = *ai + ti;
      }
    }
  }
}

namespace {
// Every column's transform at once: the butterflies of transform1d along the columns,
// each a loop over a whole row (contiguous, so the compiler vectorises it; the same
// operations in the same order as transform1d's, so the same bits).
void columns(float* re, float* im, bool inverse) {
  constexpr int n = kFftSide;
  for (int i = 0; i < n; ++i) {
    const int j = reverseBits(i);
    if (j <= i) continue;
    float* ri = re + i * n;
    float* rj = re + j * n;
    float* ii = im + i * n;
    float* ij = im + j * n;
    for (int x = 0; x < n; ++x) {
      const float tr = ri[x], ti = ii[x];
      ri[x] = rj[x];
      ii[x] = ij[x];
      rj[x] = tr;
      ij[x] = ti;
    }
  }
  const float sign = inverse ? 1.f : -1.f;
  for (int half = 1; half < n; half *= 2) {
    const int twStep = n / (2 * half);
    for (int k = 0; k < half; ++k) {
      const float wr = kCos[k * twStep];
      const float wi = sign * kSin[k * twStep];
      for (int s = k; s < n; s += 2 * half) {
        float* __restrict ar = re + s * n;
        float* __restrict ai = im + s * n;
        float* __restrict br = re + (s + half) * n;
        float* __restrict bi = im + (s + half) * n;
        for (int x = 0; x < n; ++x) {
          const float tr = wr * br[x] - wi * bi[x];
          const float ti = wr * bi[x] + wi * br[x];
          br[x] = ar[x] - tr;
          bi[x] = ai[x] - ti;
          ar[x] = ar[x] + tr;
          ai[x] = ai[x] + ti;
        }
      }
    }
  }
}

void transpose(float* p) {
  for (int y = 0; y < kFftSide; ++y)
    for (int x = y + 1; x < kFftSide; ++x) {
      const float t = p[y * kFftSide + x];
      p[y * kFftSide + x] = p[x * kFftSide + y];
      p[x * kFftSide + y] = t;
    }
}
}  // namespace

float cosTurn(int k) {
  k &= kFftSide - 1;
  return k < kFftSide / 2 ? kCos[k] : -kCos[k - kFftSide / 2];
}

void forward2d(float* re, float* im) {
  columns(re, im, false);
  transpose(re);
  transpose(im);
  columns(re, im, false);
}

void inverse2d(float* re, float* im) {
  columns(re, im, true);
  transpose(re);
  transpose(im);
  columns(re, im, true);
  constexpr float scale = 1.f / static_cast<float>(kFftSize);
  for (int i = 0; i < kFftSize; ++i) {
    re[i] *= scale;
    im[i] *= scale;
  }
}

void forwardRealPair(const float* a, const float* b, float* ar, float* ai, float* br, float* bi) {
  // Z = FFT(a + i b); A[k] = (Z[k] + conj Z[-k]) / 2, B[k] = (Z[k] - conj Z[-k]) / 2i.
  // Z is built in (br, bi) and read from there while A goes to (ar, ai): B is written
  // last, element pairs (k, -k) together.
  for (int i = 0; i < kFftSize; ++i) {
    br[i] = a[i];
    bi[i] = b[i];
  }
  forward2d(br, bi);
  constexpr int m = kFftSide - 1;
  for (int y = 0; y < kFftSide; ++y) {
    const int ny = (kFftSide - y) & m;
    for (int x = 0; x < kFftSide; ++x) {
      const int k = y * kFftSide + x;
      const int nk = ny * kFftSide + ((kFftSide - x) & m);
      if (nk < k) continue;  // the pair was done from its other end
      const float zr = br[k], zi = bi[k], nr = br[nk], ni = bi[nk];
      // A[k] = ((zr + nr) + i (zi - ni)) / 2;  B[k] = ((zi + ni) - i (zr - nr)) / 2.
      ar[k] = 0.5f * (zr + nr);
      ai[k] = 0.5f * (zi - ni);
      ar[nk] = 0.5f * (nr + zr);
      ai[nk] = 0.5f * (ni - zi);
      br[k] = 0.5f * (zi + ni);
      bi[k] = 0.5f * (nr - zr);
      br[nk] = 0.5f * (ni + zi);
      bi[nk] = 0.5f * (zr - nr);
    }
  }
}

}  // namespace cuetrack::fft
