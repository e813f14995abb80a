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

// ---- Budgets ---------------------------------------------------------------
// Whole tracker, everything included, at 640x480: the limit.
inline constexpr std::size_t kTrackerBudgetBytes = 16u * 1024u * 1024u;

}  // namespace cuetrack
