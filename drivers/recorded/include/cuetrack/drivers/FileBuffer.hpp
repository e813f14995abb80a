// Whole-file reads into a reusable buffer with POSIX calls only (fopen would malloc a
// FILE per call): after the first frame of a given size, reading allocates nothing.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace cuetrack::rec {

// A recording's file paths are built in 1 KiB buffers (folder + file name) and its error
// lines in similar ones: a longer folder path is refused up front, in one line, rather
// than cut short.
inline constexpr size_t kMaxPathChars = 900;
// True (with "PATH...: path longer than N characters" in err) when path is too long.
bool pathTooLong(const char* path, char* err, size_t errLen);

// Replaces buf's contents with the file's bytes. On failure writes "path: reason" to err.
// Anything but a regular file (a FIFO, a device, a folder) is refused without blocking.
bool readFile(const char* path, std::vector<uint8_t>& buf, char* err, size_t errLen);
// Writes all bytes (creating/truncating the file). On failure writes "path: reason".
bool writeFile(const char* path, const void* data, size_t len, char* err, size_t errLen);
bool writeFile2(const char* path, const void* a, size_t aLen, const void* b, size_t bLen, char* err,
                size_t errLen);
bool isDirectory(const char* path);
bool isFile(const char* path);
long long fileSize(const char* path);  // bytes; -1 when it cannot be read
// Anything by that name (a file, folder, FIFO, even a dangling symlink). An optional file
// of a recording is read when it exists, so one of the wrong kind is reported, not ignored.
bool exists(const char* path);
// mkdir -p; on failure writes "path: reason".
bool makeDirectories(const char* path, char* err, size_t errLen);
// True (with "dir: already holds a recording (NAME); ..." in err) when dir holds a
// fakenect, RGB-D or OTB recording's file or folder: INDEX.txt, rgb/, depth/, img/,
// groundtruth.txt, groundtruth_rect.txt or intrinsics.txt. The writers refuse such a
// folder: frames of the old recording would mix with the new ones.
bool holdsRecording(const char* dir, char* err, size_t errLen);
// A path's last part without its extension ("a/b/seq.avi" -> "seq"; trailing '/' ignored).
std::string fileStem(const std::string& path);

}  // namespace cuetrack::rec
