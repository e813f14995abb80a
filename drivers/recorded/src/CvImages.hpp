// What the OpenCV-backed readers and writers share (private to drivers/recorded):
// their reusable cv::Mat buffers and the conversions between OpenCV's images and frames.
// Defined in ImageLoaders.cpp.
#pragma once

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack {

// Decoders reuse these between frames, so reading allocates only when a size changes.
struct CvImages {
  cv::Mat bgr, depth, rgb, small;
};

// Colour as BGR, but a 16-bit image stays 16-bit so that it can be refused rather than
// scaled down without a word (8-bit images read exactly as with IMREAD_COLOR alone).
inline constexpr int kColourRead = cv::IMREAD_COLOR | cv::IMREAD_ANYDEPTH;

// "8-bit", "16-bit", ... for errors about an image's sample type.
const char* depthName(int cvDepth);

// BGR (or grey, or BGRA) Mat -> the slot's RGB, through rgbScratch; false when too large.
bool copyColour(const cv::Mat& src, cv::Mat& rgbScratch, FrameSlot& out);
// The same for colour-only sources of any size: a frame larger than the slot is scaled
// down into it (aspect kept, pixel-area averaging), out.scale says how (FrameScale.hpp).
void copyColourFit(const cv::Mat& src, CvImages& scratch, FrameSlot& out);

}  // namespace cuetrack
