// Every tool's command line, on CLI11: the options are declared once, and the parser,
// the checks and --help all come from those declarations.
//
// One convention for every tool (README): `--opt value` and `--opt=value` both; an option
// given twice is refused ("--box given twice": a second --box appended to a service's
// settings must not silently replace the first); a bad command line is one line on
// stderr, "TOOL: what is wrong", naming the option, and exit code 2; --help (-h) prints
// the generated help, ending with the tool's exit codes, on stdout and exits 0 (1 when
// stdout cannot be written).
#pragma once

#include <CLI/CLI.hpp>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace cuetrack::cli {

inline constexpr int kExitFailed = 1;  // the run failed (a source, device or write), in every tool
inline constexpr int kExitUsage = 2;   // a bad command line, in every tool

// How a bad value is quoted in the error line: --frames 'abc' or --frames abc (each tool
// keeps the form its messages, scripts and tests have always had).
enum class Quotes : uint8_t { Value, None };

// Thrown by a conversion or check: the whole error line after "TOOL: ".
class BadCommandLine : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Converts an option's text into its destination: "" when it took it, else why not (the
// error line is then "NAME 'VALUE': WHY").
using Convert = std::function<std::string(const std::string& value)>;

class Command {
 public:
  // tool: the program's name in messages; about: the first lines of --help; exitCodes:
  // its last ("exit codes: 0 ..., 2 bad command line, ...").
  Command(std::string tool, std::string about, std::string exitCodes, Quotes q = Quotes::Value);

  // An option with a value (typeName as --help shows it: N, WxH, FILE...).
  CLI::Option* option(const std::string& name, const std::string& typeName, const std::string& help,
                      Convert convert);
  // Any text.
  CLI::Option* text(const std::string& name, const std::string& typeName, const std::string& help,
                    std::string* out);
  // A whole decimal number in [lo, hi] (no sign on a count, no 0x, no spaces).
  CLI::Option* number(const std::string& name, const std::string& typeName, const std::string& help,
                      long lo, long hi, long* out);
  CLI::Option* number(const std::string& name, const std::string& typeName, const std::string& help,
                      long lo, long hi, int* out);
  // A switch without a value.
  CLI::Option* flag(const std::string& name, const std::string& help, bool* out);
  // Positional arguments, in order (none to many).
  CLI::Option* positionals(const std::string& name, const std::string& help,
                           std::vector<std::string>* out);

  // A repeatable option (--send A --send B): every value, in order.
  CLI::Option* list(const std::string& name, const std::string& typeName, const std::string& help,
                    std::vector<std::string>* out);

  // Parses argv. Returns -1 to go on, else what main returns: 0 after --help (1 when
  // stdout could not be written), kExitUsage after one line on stderr.
  int parse(int argc, const char* const* argv);
  // The same without printing: Help, or Error with the line (without "TOOL: ") in *error.
  enum class Parsed : uint8_t { Run, Help, Error };
  Parsed check(int argc, const char* const* argv, std::string* error);
  // The same with the line, control characters as '?', in a caller's buffer.
  Parsed check(int argc, const char* const* argv, char* error, size_t errorLen);
  // A check after parsing (options that need each other, a value known only then): one
  // line on stderr, "TOOL: LINE", and kExitUsage.
  int fail(const std::string& line) const;
  // The error line for a bad value of an option, in this tool's quoting.
  std::string badValue(const std::string& name, const std::string& value,
                       const std::string& why) const;

  bool given(const std::string& name) const;  // the option was on the command line
  std::string help() const;
  CLI::App& app() { return _app; }
  const std::string& tool() const { return _tool; }

 private:
  std::string _tool;
  Quotes _quotes;
  CLI::App _app;
};

// A control character (a newline in an argument) printed as '?', so an error stays one line.
std::string printable(const std::string& s);

}  // namespace cuetrack::cli
