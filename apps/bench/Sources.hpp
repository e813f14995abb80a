// Opens a SEQUENCE argument with the project's readers (drivers/): synth:<scene>
// directly, everything else through the recorded-sequence factory when it is built.
#pragma once

#include <memory>
#include <string>

#include "Options.hpp"
#include "cuetrack/drivers/FrameSource.hpp"

namespace cuetrack::bench {

// nullptr with one line in *err when the sequence cannot be opened.
std::unique_ptr<FrameSource> openSequence(const SequenceArg& arg, const Options& options,
                                          std::string* err);

// The first line of the ground truth of a BoBoT video (NAME.gt.txt beside NAME.avi, or
// --gt), which BoBoT result files must repeat; empty for other inputs.
std::string bobotHeader(const SequenceArg& arg);

}  // namespace cuetrack::bench
