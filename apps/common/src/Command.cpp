#include "cuetrack/cli/Command.hpp"

#include <cstdio>

#include "cuetrack/cli/Values.hpp"
#include "cuetrack/platform/StdoutCheck.hpp"

namespace cuetrack::cli {

std::string printable(const std::string& s) {
  std::string out = s;
  for (char& c : out)
    if (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) c = '?';
  return out;
}

Command::Command(std::string tool, std::string about, std::string exitCodes, Quotes q)
    : _tool(std::move(tool)), _quotes(q), _app(std::move(about), _tool) {
  _app.footer(std::move(exitCodes));
  _app.get_formatter()->column_width(28);
  _app.get_formatter()->label("OPTIONS", "OPTION...");
  // Every option may come twice as far as CLI11 goes: parse() refuses that itself, with
  // one message for an option with a value and a switch alike.
  _app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
  // Unknown arguments are collected, then named in parse()'s one line.
  _app.allow_extras();
}

std::string Command::badValue(const std::string& name, const std::string& value,
                              const std::string& why) const {
  const std::string v = printable(value);
  return name + (_quotes == Quotes::Value ? " '" + v + "'" : " " + v) + ": " + why;
}

CLI::Option* Command::option(const std::string& name, const std::string& typeName,
                             const std::string& help, Convert convert) {
  auto take = [this, name, convert](const std::string& value) {
    const std::string why = convert(value);
    if (!why.empty()) throw BadCommandLine(badValue(name, value, why));
  };
  return _app.add_option_function<std::string>(name, take, help)->type_name(typeName);
}

CLI::Option* Command::text(const std::string& name, const std::string& typeName,
                           const std::string& help, std::string* out) {
  return option(name, typeName, help, [out](const std::string& v) {
    *out = v;
    return std::string();
  });
}

CLI::Option* Command::number(const std::string& name, const std::string& typeName,
                             const std::string& help, long lo, long hi, long* out) {
  return option(name, typeName, help,
                [lo, hi, out](const std::string& v) { return wholeNumber(v, lo, hi, out); });
}

CLI::Option* Command::number(const std::string& name, const std::string& typeName,
                             const std::string& help, long lo, long hi, int* out) {
  return option(name, typeName, help, [lo, hi, out](const std::string& v) {
    long n = 0;
    std::string why = wholeNumber(v, lo, hi, &n);
    if (why.empty()) *out = static_cast<int>(n);
    return why;
  });
}

CLI::Option* Command::flag(const std::string& name, const std::string& help, bool* out) {
  return _app.add_flag(name, *out, help);
}

CLI::Option* Command::positionals(const std::string& name, const std::string& help,
                                  std::vector<std::string>* out) {
  return _app.add_option(name, *out, help)
      ->type_name("")
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

bool Command::given(const std::string& name) const {
  return _app.count(name) > 0;
}

std::string Command::help() const {
  return _app.help();
}

int Command::fail(const std::string& line) const {
  std::fprintf(stderr, "%s: %s\n", _tool.c_str(), printable(line).c_str());
  return kExitUsage;
}

CLI::Option* Command::list(const std::string& name, const std::string& typeName,
                           const std::string& help, std::vector<std::string>* out) {
  return _app.add_option(name, *out, help)
      ->type_name(typeName)
      ->expected(1)
      ->allow_extra_args(false)  // --send A PORT: PORT is not a second --send
      ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
}

Command::Parsed Command::check(int argc, const char* const* argv, std::string* error) {
  try {
    _app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    return Parsed::Help;
  } catch (const BadCommandLine& e) {
    *error = e.what();
    return Parsed::Error;
  } catch (const CLI::ArgumentMismatch& e) {
    // "--frames: 1 required N missing": an option at the end without its value.
    const std::string what = e.what();
    const size_t colon = what.find(':');
    if (colon != std::string::npos && what.find("missing") != std::string::npos)
      *error = what.substr(0, colon) + " needs a value (see --help)";
    else
      *error = what + " (see --help)";
    return Parsed::Error;
  } catch (const CLI::ParseError& e) {
    *error = std::string(e.what()) + " (see --help)";
    return Parsed::Error;
  }
  // A repeatable option (list(), positionals) collects every value; any other comes once.
  for (const CLI::Option* o : _app.get_options()) {
    if (o->get_multi_option_policy() == CLI::MultiOptionPolicy::TakeAll || o->count() < 2) continue;
    *error = o->get_name() + " given twice";
    return Parsed::Error;
  }
  const std::vector<std::string> extra = _app.remaining();
  if (!extra.empty()) {
    const std::string& a = extra.front();
    *error = (a.size() > 1 && a[0] == '-' ? "unknown option '" : "unexpected argument '") + a +
             "' (see --help)";
    return Parsed::Error;
  }
  return Parsed::Run;
}

Command::Parsed Command::check(int argc, const char* const* argv, char* error, size_t errorLen) {
  std::string line;
  const Parsed parsed = check(argc, argv, &line);
  if (parsed == Parsed::Error) std::snprintf(error, errorLen, "%s", printable(line).c_str());
  return parsed;
}

int Command::parse(int argc, const char* const* argv) {
  std::string error;
  switch (check(argc, argv, &error)) {
    case Parsed::Help:
      std::fputs(_app.help().c_str(), stdout);
      return platform::stdoutWritten(_tool.c_str()) ? 0 : 1;
    case Parsed::Error:
      return fail(error);
    case Parsed::Run:
      break;
  }
  return -1;
}

}  // namespace cuetrack::cli
