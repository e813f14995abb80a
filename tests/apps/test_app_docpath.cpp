// The doc the closing lines name, found where the program is: installed or in its clone.
#include <catch2/catch.hpp>

#include <sys/stat.h>

#include "DocPath.hpp"
#include "TempDir.hpp"

using cuetrack::app::findDoc;
using cuetrack::test::TempDir;
using cuetrack::test::writeText;

namespace {
void mkdirs(const TempDir& tmp, std::initializer_list<const char*> dirs) {
  for (const char* d : dirs) REQUIRE(mkdir((tmp / d).c_str(), 0755) == 0);
}
}  // namespace

TEST_CASE("findDoc: installed under PREFIX/share/doc/cuetrack, else in the clone, else as named") {
  TempDir tmp;
  mkdirs(tmp, {"bin", "share", "share/doc", "share/doc/cuetrack", "share/doc/cuetrack/docs"});
  writeText(tmp / "share/doc/cuetrack/docs/first-hour.md", "x");
  CHECK(findDoc(tmp / "bin/cuetrack", "docs/first-hour.md") ==
        tmp / "share/doc/cuetrack/docs/first-hour.md");

  mkdirs(tmp, {"clone", "clone/docs", "clone/build", "clone/build/host", "clone/build/host/bin"});
  writeText(tmp / "clone/docs/first-hour.md", "x");
  CHECK(findDoc(tmp / "clone/build/host/bin/cuetrack", "docs/first-hour.md") ==
        tmp / "clone/docs/first-hour.md");

  // Neither there: the name as the docs give it, relative to a clone.
  CHECK(findDoc(tmp / "clone/build/host/bin/cuetrack", "docs/kinect.md") == "docs/kinect.md");
  CHECK(findDoc("cuetrack", "docs/first-hour.md") == "docs/first-hour.md");
}
