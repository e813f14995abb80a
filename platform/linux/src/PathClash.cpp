#include "cuetrack/platform/linux/PathClash.hpp"

#include <dirent.h>
#include <fcntl.h>
#include <limits.h>
#include <stdlib.h>
#include <sys/stat.h>

#include <cstdio>
#include <cstring>

namespace cuetrack::platform {
namespace {

struct Resolved {
  bool exists = false;
  bool linked = false;  // a file with more than one name (a hard link)
  bool isDir = false;
  bool isDevice = false;
  dev_t dev = 0;
  ino_t ino = 0;
  char path[PATH_MAX + 256] = "";  // absolute, symlinks resolved (a new file: its folder's)
};

void resolve(const char* p, Resolved* r) {
  struct stat st {};
  if (::stat(p, &st) == 0) {
    r->exists = true;
    r->isDir = S_ISDIR(st.st_mode);
    r->isDevice = S_ISCHR(st.st_mode) || S_ISBLK(st.st_mode);
    r->dev = st.st_dev;
    r->ino = st.st_ino;
    r->linked = S_ISREG(st.st_mode) && st.st_nlink > 1;
    char real[PATH_MAX];
    std::snprintf(r->path, sizeof r->path, "%s", ::realpath(p, real) ? real : p);
    return;
  }
  // Not there yet: its folder resolved, plus its name.
  const char* slash = std::strrchr(p, '/');
  char dir[PATH_MAX];
  const char* name = p;
  if (slash == nullptr) {
    std::snprintf(dir, sizeof dir, ".");
  } else {
    std::snprintf(dir, sizeof dir, "%.*s", static_cast<int>(slash == p ? 1 : slash - p), p);
    name = slash + 1;
  }
  char real[PATH_MAX];
  if (::realpath(dir, real) == nullptr) {
    std::snprintf(r->path, sizeof r->path, "%s", p);  // its folder is missing: opening says so
    return;
  }
  std::snprintf(r->path, sizeof r->path, "%s%s%s", real, std::strcmp(real, "/") == 0 ? "" : "/",
                name);
}

bool sameFile(const Resolved& a, const Resolved& b) {
  if (a.exists && b.exists) return a.dev == b.dev && a.ino == b.ino;
  return std::strcmp(a.path, b.path) == 0;
}

// A hard link's other name may be anywhere in the folder: look for its inode, two levels
// deep (a recording's rgb/ and depth/), only for files that have another name.
bool holdsInode(const char* dir, const Resolved& file, int depth) {
  DIR* d = ::opendir(dir);
  if (d == nullptr) return false;
  bool found = false;
  while (const dirent* e = ::readdir(d)) {
    if (std::strcmp(e->d_name, ".") == 0 || std::strcmp(e->d_name, "..") == 0) continue;
    struct stat st {};
    if (::fstatat(::dirfd(d), e->d_name, &st, AT_SYMLINK_NOFOLLOW) != 0) continue;
    if (st.st_dev == file.dev && st.st_ino == file.ino) {
      found = true;
      break;
    }
    if (S_ISDIR(st.st_mode) && depth > 0) {
      char sub[PATH_MAX];
      std::snprintf(sub, sizeof sub, "%s/%s", dir, e->d_name);
      if (holdsInode(sub, file, depth - 1)) {
        found = true;
        break;
      }
    }
  }
  ::closedir(d);
  return found;
}

bool inside(const Resolved& file, const Resolved& folder) {
  if (!folder.isDir) return false;
  const size_t n = std::strlen(folder.path);
  const bool root = n == 1 && folder.path[0] == '/';
  if (std::strncmp(file.path, folder.path, n) == 0 && (root || file.path[n] == '/')) return true;
  return file.linked && holdsInode(folder.path, file, 2);
}

}  // namespace

bool checkPathClashes(const NamedPath* outputs, int outputCount, const NamedPath* inputs,
                      int inputCount, char* err, size_t errLen) {
  for (int i = 0; i < outputCount; ++i) {
    Resolved out, other;
    resolve(outputs[i].path, &out);
    if (out.isDevice) continue;
    for (int k = 0; k < inputCount; ++k) {
      other = Resolved{};
      resolve(inputs[k].path, &other);
      if (!other.exists || other.isDevice) continue;
      if (sameFile(out, other) || inside(out, other)) {
        std::snprintf(err, errLen, "%s %s %s %s %s: an output may not overwrite an input",
                      outputs[i].what, outputs[i].path,
                      other.isDir && !sameFile(out, other) ? "is inside" : "is the same file as",
                      inputs[k].what, inputs[k].path);
        return false;
      }
    }
    for (int k = i + 1; k < outputCount; ++k) {
      other = Resolved{};
      resolve(outputs[k].path, &other);
      if (!other.isDevice && sameFile(out, other)) {
        std::snprintf(err, errLen,
                      "%s %s and %s %s are the same file: one would overwrite the other",
                      outputs[i].what, outputs[i].path, outputs[k].what, outputs[k].path);
        return false;
      }
    }
  }
  return true;
}

}  // namespace cuetrack::platform
