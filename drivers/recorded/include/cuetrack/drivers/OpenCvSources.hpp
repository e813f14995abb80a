// Every OpenCV-backed reader and writer (host only; library cuetrack_recorded_cv, built
// when CUETRACK_WITH_OPENCV), one format to a header:
//   BobotVideo.hpp     BoBoT video: NAME.avi + NAME.gt.txt, reader and writer
//   RgbdFolder.hpp     RGB-D folder: rgb/, depth/, groundtruth.txt, intrinsics.txt
//   OtbFolder.hpp      OTB folder: img/, groundtruth_rect.txt
//   StillPan.hpp       pan: a real RGB-D still, panned
//   StillScene.hpp     still: a synthetic scene's objects in a real RGB-D still
//   RandomScene.hpp    rand:SEED:DATA a drawn scene over the real stills
//   ImageLoaders.hpp   whole stills (colour, 16-bit depth) for the last two and the tests
// No OpenCV type appears in them: decoders live in the .cpp files.
#pragma once

#include "cuetrack/drivers/BobotVideo.hpp"
#include "cuetrack/drivers/ImageLoaders.hpp"
#include "cuetrack/drivers/OtbFolder.hpp"
#include "cuetrack/drivers/RandomScene.hpp"
#include "cuetrack/drivers/RgbdFolder.hpp"
#include "cuetrack/drivers/StillPan.hpp"
#include "cuetrack/drivers/StillScene.hpp"
