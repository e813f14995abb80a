// A box the user typed (--box, a START) against the image it is for: does it read better
// as corners? X0,Y0,X1,Y1 typed where X,Y,W,H is meant runs past the image, and the tracker
// would follow the part inside: the wrong box.
#pragma once

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack::app {

// The box runs past the image as X,Y,W,H but fits it as corners X0,Y0,X1,Y1 (X1 > X0,
// Y1 > Y0): likely corners. *asXywh: the box those corners mean.
bool looksLikeCorners(const Box& box, int width, int height, Box* asXywh);

}  // namespace cuetrack::app
