// Reporters writing one line per report in one write(2): stderr with a program
// prefix ("cuetrack: ..."), or plain lines to stdout/stderr (the listener's messages).
#pragma once

#include "cuetrack/platform/Reporter.hpp"

namespace cuetrack::platform {

class StderrReporter final : public Reporter {
 public:
  explicit StderrReporter(const char* prefix) : _prefix(prefix) {}
  void report(const char* line) override;

 private:
  const char* _prefix;
};

enum class StdStream : unsigned char { Out, Err };

class LineReporter final : public Reporter {
 public:
  explicit LineReporter(StdStream stream) : _stream(stream) {}
  void report(const char* line) override;
  bool failed() const { return _failed; }  // a line could not be written (/dev/full...)

 private:
  StdStream _stream;
  bool _failed = false;
};

}  // namespace cuetrack::platform
