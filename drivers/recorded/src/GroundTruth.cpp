#include "cuetrack/drivers/GroundTruth.hpp"

#include <cstdio>
#include <cstring>

#include "cuetrack/drivers/FileBuffer.hpp"
#include "cuetrack/drivers/RecordedParsers.hpp"

namespace cuetrack {

bool GroundTruth::load(const char* path, GtFormat format, char* err, size_t errLen) {
  std::vector<uint8_t> text;
  if (!rec::readFile(path, text, err, errLen)) return false;
  return parse(reinterpret_cast<const char*>(text.data()), text.size(), path, format, err, errLen);
}

bool GroundTruth::parse(const char* text, size_t len, const char* name, GtFormat format, char* err,
                        size_t errLen) {
  _values.clear();
  _header.clear();
  _format = format;
  _loaded = false;
  size_t pos = 0;
  const char* line = nullptr;
  size_t lineLen = 0;
  int lineNo = 0;
  bool first = true;
  char why[160];
  while (rec::nextLine(text, len, &pos, &line, &lineLen)) {
    ++lineNo;
    if (rec::blankLine(line, lineLen)) continue;
    float box[4];
    if (format == GtFormat::Bobot) {
      int idx = -1;
      const bool ok = rec::parseBobotLine(line, lineLen, &idx, box, why, sizeof why);
      if (first && !ok) {
        // The header line (BoBoT's evaluator compares it with the result file's).
        _header.assign(line, lineLen);
        first = false;
        continue;
      }
      first = false;
      if (!ok) {
        std::snprintf(err, errLen, "%s:%d: %s", name, lineNo, why);
        return false;
      }
      if (idx != count()) {
        std::snprintf(err, errLen, "%s:%d: frame index %d, expected %d", name, lineNo, idx,
                      count());
        return false;
      }
    } else if (!rec::parseOtbLine(line, lineLen, box, why, sizeof why)) {
      std::snprintf(err, errLen, "%s:%d: %s", name, lineNo, why);
      return false;
    }
    _values.insert(_values.end(), box, box + 4);
  }
  _loaded = true;
  return true;
}

bool GroundTruth::boxAt(int i, int width, int height, Box* out) const {
  if (i < 0 || i >= count()) return false;
  const float* v = &_values[static_cast<size_t>(i) * 4];
  Box b;
  if (_format == GtFormat::Bobot) {
    b = {v[0] * static_cast<float>(width), v[1] * static_cast<float>(height),
         v[2] * static_cast<float>(width), v[3] * static_cast<float>(height)};
  } else {
    b = {v[0] - 1.f, v[1] - 1.f, v[2], v[3]};  // 1-based -> 0-based
  }
  *out = b.empty() ? Box{} : b;
  return true;
}

bool GtWriter::open(const char* path, GtFormat format, const char* header, char* err,
                    size_t errLen) {
  close();
  _file = std::fopen(path, "wb");
  if (!_file) {
    std::snprintf(err, errLen, "%s: cannot create", path);
    return false;
  }
  _format = format;
  _next = 0;
  if (format == GtFormat::Bobot) std::fprintf(_file, "%s\r\n", header ? header : "");
  return true;
}

bool GtWriter::write(const Box& box, int width, int height) {
  if (!_file) return false;
  int n;
  if (_format == GtFormat::Bobot) {
    if (box.empty() || width <= 0 || height <= 0)
      n = std::fprintf(_file, "%d 0 0 0 0\r\n", _next);
    else
      n = std::fprintf(_file, "%d %.7f %.7f %.7f %.7f\r\n", _next,
                       static_cast<double>(box.x / static_cast<float>(width)),
                       static_cast<double>(box.y / static_cast<float>(height)),
                       static_cast<double>(box.w / static_cast<float>(width)),
                       static_cast<double>(box.h / static_cast<float>(height)));
  } else {
    if (box.empty())
      n = std::fprintf(_file, "0,0,0,0\n");
    else
      n = std::fprintf(_file, "%.3f,%.3f,%.3f,%.3f\n", static_cast<double>(box.x + 1.f),
                       static_cast<double>(box.y + 1.f), static_cast<double>(box.w),
                       static_cast<double>(box.h));
  }
  ++_next;
  return n > 0;
}

bool GtWriter::close() {
  if (!_file) return true;
  const bool ok = std::fclose(_file) == 0;
  _file = nullptr;
  return ok;
}

}  // namespace cuetrack
