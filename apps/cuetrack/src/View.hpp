// What cuetrack shows on a screen or writes as pictures (host builds with OpenCV): the
// display probe, the picker (--select), the grid snapshot (--snapshot), the video
// (--video) and the live window (--show), each in a file of its own. Board builds link
// ViewStub.cpp instead, whose every call fails with "not built with OpenCV".
#pragma once

#include "DisplayProbe.hpp"
#include "LiveView.hpp"
#include "Picker.hpp"
#include "Snapshot.hpp"
#include "VideoOut.hpp"
#include "ViewTrack.hpp"
