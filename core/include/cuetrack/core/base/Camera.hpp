// The pinhole camera model on Eigen fixed-size vectors (no allocation: core builds
// with EIGEN_NO_MALLOC). Camera coordinates [mm]: x right, y down, z forward.
#pragma once

#include <Eigen/Core>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack {

// The image point [px] of camera point pMm (pMm.z() > 0).
inline Eigen::Vector2f project(const CameraIntrinsics& k, const Eigen::Vector3f& pMm) {
  const float inv = 1.f / pMm.z();
  return Eigen::Vector2f(k.fx * pMm.x() * inv + k.cx, k.fy * pMm.y() * inv + k.cy);
}

// The camera point at depth zMm on the viewing ray through image point (u, v) [px].
inline Eigen::Vector3f backProject(const CameraIntrinsics& k, float u, float v, float zMm) {
  return Eigen::Vector3f((u - k.cx) * zMm / k.fx, (v - k.cy) * zMm / k.fy, zMm);
}

}  // namespace cuetrack
