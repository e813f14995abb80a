#include "cuetrack/core/config/InitError.hpp"

namespace cuetrack {

const char* toString(InitError e) {
  switch (e) {
    case InitError::None:
      return "ok";
    case InitError::EmptyBox:
      return "empty box (w or h <= 0)";
    case InitError::BoxOutsideImage:
      return "box does not intersect the image";
    case InitError::BoxTooSmall:
      return "box smaller than 3x3 px (the smallest target tracked)";
    case InitError::NoColour:
      return "frame has no colour image";
    case InitError::ImageTooLarge:
      return "image larger than 640x480";
    case InitError::NoDepth:
      return "no depth (or no valid depth inside the box) for a depth configuration";
    case InitError::NoIntrinsics:
      return "3D state space needs camera intrinsics";
    case InitError::BoxTooWideFor3d:
      return "box too wide for the 3D cylinder (w >= fx px)";
  }
  return "unknown error";
}

}  // namespace cuetrack
