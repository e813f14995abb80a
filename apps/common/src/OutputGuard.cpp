#include "cuetrack/cli/OutputGuard.hpp"

#include <cstring>

#include "cuetrack/platform/linux/PathClash.hpp"

namespace cuetrack::cli {
namespace {

bool startsWith(const std::string& s, const char* prefix) {
  return s.compare(0, std::strlen(prefix), prefix) == 0;
}

// A video's ground truth beside it: NAME.gt.txt (BoBoT) and NAME.txt (OTB), NAME being
// the path without its extension.
std::string stem(const std::string& path) {
  const size_t slash = path.find_last_of('/');
  const size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash) ||
      dot == (slash == std::string::npos ? 0 : slash + 1))
    return path;
  return path.substr(0, dot);
}

}  // namespace

void OutputGuard::input(const std::string& what, const std::string& path) {
  if (!path.empty()) _inputs.push_back({what, path});
}

void OutputGuard::source(const std::string& what, const std::string& spec) {
  if (spec.empty() || startsWith(spec, "synth") || startsWith(spec, "kinect") ||
      startsWith(spec, "camera"))
    return;
  if (startsWith(spec, "rand:")) {
    const size_t data = spec.find(':', 5);
    if (data != std::string::npos) input(what + "'s data", spec.substr(data + 1));
    return;
  }
  const bool still = startsWith(spec, "still:");
  if (still || startsWith(spec, "pan:")) {
    // pan:RGB,DEPTH,... / still:RGB,DEPTH,...:SCENE@...: the files named, before any ':'.
    const size_t from = still ? 6 : 4;
    const size_t colon = spec.find(':', from);
    const std::string files =
        spec.substr(from, colon == std::string::npos ? std::string::npos : colon - from);
    size_t at = 0;
    while (at < files.size()) {
      const size_t comma = files.find(',', at);
      const size_t end = comma == std::string::npos ? files.size() : comma;
      input(what, files.substr(at, end - at));
      at = end + 1;
    }
    return;
  }
  input(what, spec);
  const std::string name = stem(spec);
  if (name != spec) {
    input(what + "'s ground truth", name + ".gt.txt");
    input(what + "'s ground truth", name + ".txt");
  }
}

void OutputGuard::output(const std::string& what, const std::string& path) {
  if (path.empty() || path == "-") return;
  for (const Named& o : _outputs)
    if (o.what == what && o.path == path) return;  // named again (checkLater): one output
  _outputs.push_back({what, path});
}

void OutputGuard::outputFolder(const std::string& what, const std::string& path) {
  if (!path.empty()) _folders.push_back({what, path});
}

bool OutputGuard::check(std::string* err) const {
  std::vector<platform::NamedPath> ins, files;
  for (const Named& i : _inputs) ins.push_back({i.what.c_str(), i.path.c_str()});
  for (const Named& o : _outputs) files.push_back({o.what.c_str(), o.path.c_str()});
  char line[2048];
  // Each output (file or folder) against the inputs, one at a time: folders may be shared.
  for (const std::vector<Named>* list : {&_outputs, &_folders})
    for (const Named& o : *list) {
      const platform::NamedPath one{o.what.c_str(), o.path.c_str()};
      if (!platform::checkPathClashes(&one, 1, ins.data(), static_cast<int>(ins.size()), line,
                                      sizeof line)) {
        *err = line;
        return false;
      }
    }
  // The files against each other.
  if (platform::checkPathClashes(files.data(), static_cast<int>(files.size()), nullptr, 0, line,
                                 sizeof line))
    return true;
  *err = line;
  return false;
}

bool OutputGuard::checkLater(const std::string& what, const std::string& path,
                             std::string* err) const {
  OutputGuard more = *this;
  more.output(what, path);
  return more.check(err);
}

}  // namespace cuetrack::cli
