// Which files are videos or images, and where a video's ground truth is (no decoding
// here: the board builds it, and the app names the file in its messages).
//
//   NAME.EXT + NAME.gt.txt   BoBoT form (header line, "i x y w h" normalised): as BoBoT's
//                            .avi and cuetrack's own writers have it
//   NAME.EXT + NAME.txt      OTB form ("x,y,w,h" in the video's own 1-based pixels, one
//                            line per frame), read when there is no NAME.gt.txt
// A ground-truth file named by the caller (SourceOptions::gtPath, --gt) is in BoBoT form
// for an .avi or a name ending in .gt.txt, in OTB form otherwise.
#pragma once

#include <string>

#include "cuetrack/drivers/GroundTruth.hpp"

namespace cuetrack::rec {

// The video extensions the factory opens (.avi .mp4 .mkv .mov .m4v .webm .mpg .mpeg .wmv),
// case-insensitive.
bool isVideoName(const char* path);
// A still image's extension (.png .jpg .jpeg .ppm .pgm .bmp), case-insensitive.
bool isImageName(const char* path);
// True when folder holds at least one image file directly (an image folder).
bool folderHoldsImages(const char* folder);
// "a video (.avi .mp4 ...)" for messages.
const char* videoExtensionsText();
// The ground-truth file beside video: NAME.gt.txt when it exists, else NAME.txt when it
// exists, else NAME.gt.txt for an .avi and NAME.txt for the others (named in messages).
std::string videoGroundTruthPath(const char* video);
// The form of the ground truth of video: of gtPath when given, else of the file beside it.
GtFormat videoGroundTruthFormat(const char* video, const char* gtPath);

}  // namespace cuetrack::rec
