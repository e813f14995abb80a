#include "cuetrack/drivers/MediaFiles.hpp"

#include <dirent.h>

#include <cctype>
#include <cstring>

#include "cuetrack/drivers/FileBuffer.hpp"

namespace cuetrack::rec {
namespace {

constexpr const char* kVideoExtensions[] = {".avi",  ".mp4", ".mkv",  ".mov", ".m4v",
                                            ".webm", ".mpg", ".mpeg", ".wmv"};

bool endsWithNoCase(const std::string& s, const char* suffix) {
  const size_t n = std::strlen(suffix);
  if (s.size() < n) return false;
  for (size_t i = 0; i < n; ++i)
    if (std::tolower(static_cast<unsigned char>(s[s.size() - n + i])) != suffix[i]) return false;
  return true;
}

std::string withoutExtension(const std::string& path) {
  const size_t dot = path.find_last_of('.');
  const size_t slash = path.find_last_of('/');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return path;
  return path.substr(0, dot);
}

}  // namespace

bool isVideoName(const char* path) {
  const std::string p = path ? path : "";
  for (const char* ext : kVideoExtensions)
    if (endsWithNoCase(p, ext)) return true;
  return false;
}

bool isImageName(const char* path) {
  const std::string p = path ? path : "";
  for (const char* ext : {".png", ".jpg", ".jpeg", ".ppm", ".pgm", ".bmp"})
    if (endsWithNoCase(p, ext)) return true;
  return false;
}

bool folderHoldsImages(const char* folder) {
  DIR* d = opendir(folder);
  if (!d) return false;
  bool found = false;
  while (dirent* e = readdir(d)) {
    if (e->d_name[0] != '.' && isImageName(e->d_name)) {
      found = true;
      break;
    }
  }
  closedir(d);
  return found;
}

const char* videoExtensionsText() {
  return "a video (.avi .mp4 .mkv .mov .m4v .webm .mpg .mpeg .wmv)";
}

std::string videoGroundTruthPath(const char* video) {
  const std::string stem = withoutExtension(video);
  const std::string bobot = stem + ".gt.txt", otb = stem + ".txt";
  if (exists(bobot.c_str())) return bobot;
  if (exists(otb.c_str())) return otb;
  return endsWithNoCase(video, ".avi") ? bobot : otb;
}

GtFormat videoGroundTruthFormat(const char* video, const char* gtPath) {
  if (gtPath) {
    return endsWithNoCase(video, ".avi") || endsWithNoCase(gtPath, ".gt.txt") ? GtFormat::Bobot
                                                                              : GtFormat::Otb;
  }
  return endsWithNoCase(videoGroundTruthPath(video), ".gt.txt") ? GtFormat::Bobot : GtFormat::Otb;
}

}  // namespace cuetrack::rec
