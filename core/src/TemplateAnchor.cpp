#include "cuetrack/core/TemplateAnchor.hpp"

#include "cuetrack/core/FastMath.hpp"

namespace cuetrack {

namespace {
// Zero-mean, unit-norm grey cell means of `win` into out (kPatchSize^2); false if flat.
bool grayCells(const FrameTables& t, const Box& win, float* out) {
  // Mean grey of each of kPatchSize^2 cells of the window (each at least one pixel), grey only:
  // 25 windows a frame, so the other channels are not worth reading.
  int xs[kPatchSize + 1], ys[kPatchSize + 1];
  const float ox = win.x - static_cast<float>(t.originX);
  const float oy = win.y - static_cast<float>(t.originY);
  for (int i = 0; i <= kPatchSize; ++i) {
    const float f = static_cast<float>(i) / static_cast<float>(kPatchSize);
    const int x = fmath::roundToInt(ox + f * win.w), y = fmath::roundToInt(oy + f * win.h);
    xs[i] = x < 0 ? 0 : (x > t.width ? t.width : x);
    ys[i] = y < 0 ? 0 : (y > t.height ? t.height : y);
  }
  constexpr int kN = kPatchSize * kPatchSize;
  float mean = 0.f;
  for (int j = 0; j < kPatchSize; ++j) {
    int y0 = ys[j], y1 = ys[j + 1];
    if (y1 <= y0) {
      if (y0 >= t.height) y0 = t.height - 1;
      y1 = y0 + 1;
    }
    for (int i = 0; i < kPatchSize; ++i) {
      int x0 = xs[i], x1 = xs[i + 1];
      if (x1 <= x0) {
        if (x0 >= t.width) x0 = t.width - 1;
        x1 = x0 + 1;
      }
      const float v = detail::rect(t.gray, t.stride, x0, y0, x1, y1) /
                      static_cast<float>((x1 - x0) * (y1 - y0));
      out[j * kPatchSize + i] = v;
      mean += v;
    }
  }
  mean /= static_cast<float>(kN);
  float ss = 0.f;
  for (int i = 0; i < kN; ++i) {
    out[i] -= mean;
    ss += out[i] * out[i];
  }
  if (!(ss > 1e-3f)) return false;
  const float inv = 1.f / fmath::sqrtf(ss);
  for (int i = 0; i < kN; ++i) out[i] *= inv;
  return true;
}
}  // namespace

TemplateAnchor::Params TemplateAnchor::paramsOf(const TrackerConfig& c) {
  Params p;
  if (!c.templateShift) p.shiftStep = 0.f;
  return p;
}

bool TemplateAnchor::capture(const FrameTables& t, const Box& win) {
  _active = _p.scaleSteps > 0 && grayCells(t, win, _anchor);
  return _active;
}

float TemplateAnchor::match(const FrameTables& t, const Box& win) {
  if (!grayCells(t, win, _probe)) return -2.f;
  float ncc = 0.f;
  for (int q = 0; q < kPatchSize * kPatchSize; ++q) ncc += _probe[q] * _anchor[q];
  return ncc;
}

Box TemplateAnchor::correct(const FrameTables& t, const Box& est) {
  int k = _p.scaleSteps;
  if (k > kMaxTemplateScaleSteps) k = kMaxTemplateScaleSteps;
  const int side = 2 * k + 1;
  const float cx = est.x + 0.5f * est.w, cy = est.y + 0.5f * est.h;
  float best = -2.f;
  int bi = k, bj = k;
  for (int j = 0; j < side; ++j) {
    const float h = est.h * fmath::fastExp(_p.scaleStep * static_cast<float>(j - k));
    for (int i = 0; i < side; ++i) {
      const float w = est.w * fmath::fastExp(_p.scaleStep * static_cast<float>(i - k));
      const float ncc = match(t, Box{cx - 0.5f * w, cy - 0.5f * h, w, h});
      if (ncc > best) {
        best = ncc;
        bi = i;
        bj = j;
      }
    }
  }
  // A poor best match: the target has turned, changed or is occluded; no information.
  if (best < _p.minNcc) return est;
  const float g = _p.gain * _p.scaleStep;
  const float w = est.w * fmath::fastExp(g * static_cast<float>(bi - k));
  const float h = est.h * fmath::fastExp(g * static_cast<float>(bj - k));
  float ncx = cx, ncy = cy;
  if (_p.shiftStep > 0.f) {
    // The best size's template, shifted by -2..2 steps of templateShiftStep of its side
    // along each axis: the centre the learnt positives drift from.
    const float bw = est.w * fmath::fastExp(_p.scaleStep * static_cast<float>(bi - k));
    const float bh = est.h * fmath::fastExp(_p.scaleStep * static_cast<float>(bj - k));
    const float stepX = _p.shiftStep * bw, stepY = _p.shiftStep * bh;
    float bestShift = -2.f;
    int si = 0, sj = 0;
    for (int dj = -2; dj <= 2; ++dj) {
      for (int di = -2; di <= 2; ++di) {
        const float x = cx + stepX * static_cast<float>(di) - 0.5f * bw;
        const float y = cy + stepY * static_cast<float>(dj) - 0.5f * bh;
        // No shift is the ladder's best box: its match is already known.
        const float ncc = di == 0 && dj == 0 ? best : match(t, Box{x, y, bw, bh});
        if (ncc > bestShift) {
          bestShift = ncc;
          si = di;
          sj = dj;
        }
      }
    }
    if (bestShift >= _p.minNcc) {
      ncx += _p.shiftGain * stepX * static_cast<float>(si);
      ncy += _p.shiftGain * stepY * static_cast<float>(sj);
    }
  }
  return Box{ncx - 0.5f * w, ncy - 0.5f * h, w, h};
}

void TemplateAnchor::moveCloud(const Box& from, const Box& to, ParticleFilter& filter, Box* boxes) {
  constexpr float g = tuning::templateAnchor::kCloudGain;
  if (!(g > 0.f) || from.empty() || to.empty()) return;
  const float sw = fmath::fastExp(g * fmath::fastLog(to.w / from.w));
  const float sh = fmath::fastExp(g * fmath::fastLog(to.h / from.h));
  const float du = g * ((to.x + 0.5f * to.w) - (from.x + 0.5f * from.w));
  const float dv = g * ((to.y + 0.5f * to.h) - (from.y + 0.5f * from.h));
  const int n = filter.size();
  for (int i = 0; i < n; ++i) {
    Particle& q = filter[i];
    q.p[0] += du;
    q.p[1] += dv;
    q.size[0] *= sw;
    q.size[1] *= sh;
    boxes[i] = particleWindow(q, false, CameraIntrinsics{});
  }
}

}  // namespace cuetrack
