// How the camera sits on the vehicle, for LANDING_TARGET's x, y, z in MAV_FRAME_BODY_FRD
// (x forward, y right, z down, origin at the vehicle's reference point).
//
// At roll = pitch = yaw = 0 the camera looks forward, upright: its optical axis is body
// x, image right is body y, image down is body z. The mounting angles then turn it, as
// body-frame Euler angles (yaw about z, then pitch about y, then roll about x, the usual
// aerospace order): pitch -90 looks straight down with the image top towards the nose.
// The offset is the camera's optical centre in the body frame [m].
#pragma once

namespace cuetrack::platform::mavlink {

struct CameraMount {
  float rollDeg = 0.f, pitchDeg = 0.f, yawDeg = 0.f;
  float offsetM[3] = {0.f, 0.f, 0.f};
};

// camM: a point in camera coordinates [m] (x right, y down, z forward). bodyM: the same
// point in MAV_FRAME_BODY_FRD [m].
void cameraToBodyFrd(const CameraMount& mount, const float camM[3], float bodyM[3]);

}  // namespace cuetrack::platform::mavlink
