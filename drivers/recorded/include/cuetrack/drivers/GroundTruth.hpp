// Ground-truth files: BoBoT (header line, then "idx x y w h" normalised to the image)
// and OTB ("x,y,w,h" in 1-based pixels). Loaded once when a sequence opens.
#pragma once

#include <cstddef>
#include <cstdio>
#include <string>
#include <vector>

#include "cuetrack/core/base/Geometry.hpp"

namespace cuetrack {

enum class GtFormat : uint8_t { Bobot, Otb };

class GroundTruth {
 public:
  // Parses a whole file; on failure err holds "path:line: reason".
  bool load(const char* path, GtFormat format, char* err, size_t errLen);
  // Same from memory (`name` only for messages).
  bool parse(const char* text, size_t len, const char* name, GtFormat format, char* err,
             size_t errLen);
  int count() const { return static_cast<int>(_values.size() / 4); }
  bool loaded() const { return _loaded; }
  GtFormat format() const { return _format; }
  const std::string& header() const { return _header; }  // BoBoT's first line
  // Box of entry i in pixels of a width x height image (BoBoT is normalised); empty
  // when the target is not visible. False when i is out of range.
  bool boxAt(int i, int width, int height, Box* out) const;

 private:
  std::vector<float> _values;  // 4 per entry, as in the file
  std::string _header;
  GtFormat _format = GtFormat::Bobot;
  bool _loaded = false;
};

// Writes ground truth in either format, one box per frame, in order.
class GtWriter {
 public:
  GtWriter() = default;
  GtWriter(const GtWriter&) = delete;
  GtWriter& operator=(const GtWriter&) = delete;
  ~GtWriter() { close(); }
  // BoBoT writes `header` as its first line (BoBoT's evaluator compares it).
  bool open(const char* path, GtFormat format, const char* header, char* err, size_t errLen);
  // Box in pixels of a width x height image; empty box = not visible.
  bool write(const Box& box, int width, int height);
  bool close();
  bool isOpen() const { return _file != nullptr; }

 private:
  std::FILE* _file = nullptr;
  GtFormat _format = GtFormat::Bobot;
  int _next = 0;
};

}  // namespace cuetrack
