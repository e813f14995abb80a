#include "cuetrack/platform/mavlink/CameraMount.hpp"

#include <cmath>

namespace cuetrack::platform::mavlink {

void cameraToBodyFrd(const CameraMount& mount, const float camM[3], float bodyM[3]) {
  constexpr double kRadPerDeg = 3.14159265358979323846 / 180.0;
  // The upright forward camera: optical axis -> x, image right -> y, image down -> z.
  const double v[3] = {camM[2], camM[0], camM[1]};
  const double r = mount.rollDeg * kRadPerDeg, p = mount.pitchDeg * kRadPerDeg,
               y = mount.yawDeg * kRadPerDeg;
  const double cr = std::cos(r), sr = std::sin(r), cp = std::cos(p), sp = std::sin(p),
               cy = std::cos(y), sy = std::sin(y);
  // R = Rz(yaw) * Ry(pitch) * Rx(roll)
  const double m[3][3] = {
      {cy * cp, cy * sp * sr - sy * cr, cy * sp * cr + sy * sr},
      {sy * cp, sy * sp * sr + cy * cr, sy * sp * cr - cy * sr},
      {-sp, cp * sr, cp * cr},
  };
  for (int i = 0; i < 3; ++i)
    bodyM[i] =
        static_cast<float>(m[i][0] * v[0] + m[i][1] * v[1] + m[i][2] * v[2] + mount.offsetM[i]);
}

}  // namespace cuetrack::platform::mavlink
