// Every compile-time capacity of the core, in one place. Each large buffer states
// its byte budget next to a static_assert so a change that breaks it fails to build.
#pragma once

#include <cstddef>
#include <cstdint>

namespace cuetrack {

// ---- Images ---------------------------------------------------------------
inline constexpr int kMaxImageWidth = 640;                           // Kinect v1 colour/depth [px]
inline constexpr int kMaxImageHeight = 480;                          // [px]
inline constexpr int kMaxPixels = kMaxImageWidth * kMaxImageHeight;  // 307,200
// The smallest window side [px] of particles and negatives.
inline constexpr float kMinWindowPx = 8.f;
// The smallest first box a user may give [px] (tracked padded: WindowPadding.hpp).
inline constexpr float kMinTargetPx = 3.f;
// Integral images carry one extra zero row and column.
inline constexpr int kMaxIntegralWidth = kMaxImageWidth + 1;
inline constexpr int kMaxIntegralHeight = kMaxImageHeight + 1;
inline constexpr int kMaxIntegralCells = kMaxIntegralWidth * kMaxIntegralHeight;  // 308,321

// Depth beyond this is treated as "no measurement". Kinect v1 reads 0.5 m to ~8 m;
// the cap also keeps any rectangle's depth sum below 2^32 (see Integral.hpp).
inline constexpr uint16_t kMaxDepthMm = 10000;

// ---- Particle filter ------------------------------------------------------
inline constexpr int kMaxParticles = 2000;  // the paper's runs use 2000

// ---- Observation model ----------------------------------------------------
inline constexpr int kMaxWeakClassifiers = 32;    // M: 23 (RGB-D) and 32 (RGB) in the paper
inline constexpr int kMaxTrainingExamples = 140;  // positives + negatives, as in the paper
inline constexpr int kNumFeatureKinds = 3;        // grayscale gradient, depth gradient, colour
inline constexpr int kDynamicFeaturesPerKind = 50;
// Pool capacity: the sparse pool is 3 kinds x (30 static + 50 dynamic) = 240; the
// dense (old) pool 3 x 84 = 252 (FeaturePool.hpp).
inline constexpr int kMaxPoolFeatures = 256;

// ---- Budgets ---------------------------------------------------------------
// Whole tracker, everything included, at 640x480: the limit.
inline constexpr std::size_t kTrackerBudgetBytes = 16u * 1024u * 1024u;
// The big buffers (each also static_asserted next to its owner):
//   integral tables    5 x 641 x 481 x 4 B             = 6,166,420 B (IntegralChannels)
//   example patches    140 x (5 x 33^2 x 4 + 132) B    = 3,067,680 B (TrainingSet)
//   response cache     256 x 140 x 20 B                =   716,800 B (ResponseCache)
//   weak classifiers   32 x (32 x 40 + 2) x 4 B        ~   164,100 B (StrongClassifier)
//   particles          2 x 2000 x 32 B + 2000 x 4 B    =   136,000 B (ParticleFilter)
//   per-particle boxes and scores 2000 x 20 B          =    40,000 B (Tracker)
//   table cells per distinct feature 32 x 2000 x 2 B   =   128,000 B (StrongClassifier)
//   correlation filter (2D) 12 x 32^2 x 4 B x 5 + scratch =  495,664 B (CorrelationFilter)
//   total                                              ~11.1 MB < 16 MiB (16,777,216 B)
inline constexpr std::size_t kIntegralBytes = 5u * kMaxIntegralCells * 4u;
inline constexpr std::size_t kPatchBytes =
    std::size_t{kMaxTrainingExamples} * (5u * 33u * 33u * 4u + 2u * 33u * 2u);
inline constexpr std::size_t kCacheBytes =
    std::size_t{kMaxPoolFeatures} * kMaxTrainingExamples * 20u;
static_assert(kIntegralBytes == 6166420u, "integral tables: 5 x 641 x 481 x 4 B");
static_assert(kPatchBytes == 3067680u, "example patches: 140 x (5 x 33^2 x 4 + 2 x 33 x 2) B");
static_assert(kCacheBytes == 716800u, "response cache: 256 x 140 x 20 B");
static_assert(kIntegralBytes + kPatchBytes + kCacheBytes + 400000u < kTrackerBudgetBytes,
              "the tracker's big buffers must fit the 16 MiB budget");

}  // namespace cuetrack
