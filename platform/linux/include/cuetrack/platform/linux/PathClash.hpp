// No output may overwrite an input or another output. Paths are compared by what they
// resolve to: the same file (device and inode, so a symlink or a hard link is caught too),
// or, for an input folder, an output anywhere inside it ("rec/INDEX.txt", a new file in a
// recording, another name of a file in it). An output that does not exist yet is resolved through
// its folder. Devices
// (/dev/null) are never a clash: writing one destroys no file.
#pragma once

#include <cstddef>

namespace cuetrack::platform {

struct NamedPath {
  const char* what;  // as the user gave it, e.g. "--out", "--source"
  const char* path;
};

// False with one line in err naming both paths when an output is an input, lies inside an
// input folder, or is another output. Inputs that do not exist are skipped (their reader
// says so).
bool checkPathClashes(const NamedPath* outputs, int outputCount, const NamedPath* inputs,
                      int inputCount, char* err, size_t errLen);

}  // namespace cuetrack::platform
