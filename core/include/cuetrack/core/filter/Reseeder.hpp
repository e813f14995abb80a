// Particles put where the appearance cue found the target (beyond the paper; with
// `correlationCue`): one in correlation::kEvery drawn at the cue's peak while tracking
// (the target may have jumped where the cloud did not reach), and, while lost, at the
// best peak of the lost scan, which searches the image a few tiles a frame.
#pragma once

#include <cstdint>

#include "cuetrack/core/base/Geometry.hpp"
#include "cuetrack/core/base/Rng.hpp"
#include "cuetrack/core/base/Span.hpp"
#include "cuetrack/core/config/Config.hpp"
#include "cuetrack/core/config/Tuning.hpp"
#include "cuetrack/core/filter/LostSearch.hpp"
#include "cuetrack/core/filter/ParticleFilter.hpp"
#include "cuetrack/core/model/IntegralChannels.hpp"

namespace cuetrack {

class Reseeder {
 public:
  static constexpr int kEvery = tuning::correlation::kEvery;
  static constexpr int kSlot = tuning::correlation::kSlot;  // particles kSlot + j kEvery
  static constexpr int kMaxMoved = kMaxParticles / kEvery + 1;
  static constexpr int kTilesPerFrame = tuning::correlation::kScanTilesPerFrame;

  // One particle in kEvery of `filter` onto window c: `from` moved there (3D: at its depth
  // on the ray through c's centre, then onto the surface there), jittered by the 2D
  // position noise; withVelocity: moving on as it jumped over dtS. Returns how many moved
  // (index(k), windows()).
  int place(const Box& c, const Particle& from, float dtS, bool withVelocity,
            const SearchView& view, const IntegralChannels& channels, Rng& rng,
            ParticleFilter& filter);
  int index(int k) const { return _index[k]; }
  // The moved particles' windows, as many as the last place() moved.
  Span<const Box> windows() const { return Span<const Box>(_windows, _moved); }

  // The lost scan: tiles `stepSides` window sides apart over the image, at the last
  // learnt window's size, visited kTilesPerFrame a frame, round and round.
  struct Tiles {
    Box last{};
    float stepSides = 0.f;
    int nx = 0, ny = 0;
    int count() const { return nx * ny; }
  };
  static Tiles tiles(const Box& last, float stepSides, int imageW, int imageH);
  Box nextTile(const Tiles& t);  // the window around which to search next
  void restartScan() { _scanTile = 0; }

 private:
  uint16_t _index[kMaxMoved] = {};  // the particles moved this frame
  Box _windows[kMaxMoved];
  int _moved = 0;
  int _scanTile = 0;  // the lost scan's next tile
};

}  // namespace cuetrack
