// Every tool's one guard for what it writes: before anything is opened for writing, no
// output may name, link to or lie inside an input (a video, its ground truth, a folder
// read), nor be another output. --force never loosens it (--force overwrites an earlier
// output, never an input). Paths are compared by what they resolve to (symlinks, "../",
// hard links: platform/linux PathClash.hpp); devices (/dev/null, a serial port) are never
// a clash.
#pragma once

#include <string>
#include <vector>

namespace cuetrack::cli {

class OutputGuard {
 public:
  // A file or folder the run reads ("--source", "--gt", "--mavlink-key"...).
  void input(const std::string& what, const std::string& path);
  // A source as the tools read it: synth:, rand:SEED, kinect and camera name no file;
  // rand:SEED:DATA reads DATA; pan:/still: the files named before a ':'; any other text is
  // a file or folder, and a file's ground truth beside it (NAME.gt.txt, NAME.txt) is an
  // input too.
  void source(const std::string& what, const std::string& spec);
  // A file the run writes ("-" for stdout is not one).
  void output(const std::string& what, const std::string& path);
  // A folder the run writes files into: it may not be, or lie inside, an input folder,
  // nor be an input file; other outputs may share it (each file it gets named by
  // output()).
  void outputFolder(const std::string& what, const std::string& path);

  // False with one line in *err naming both paths when an output is an input, lies
  // inside an input folder, or is another output; the tool then exits 2.
  bool check(std::string* err) const;
  // The same for one more output known only later (a file a tool names after what it
  // read), against the inputs and the outputs above.
  bool checkLater(const std::string& what, const std::string& path, std::string* err) const;

 private:
  struct Named {
    std::string what, path;
  };
  std::vector<Named> _inputs, _outputs, _folders;
};

}  // namespace cuetrack::cli
