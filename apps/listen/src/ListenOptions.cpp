#include "ListenOptions.hpp"

#include <cstdio>

#include "cuetrack/cli/Command.hpp"
#include "cuetrack/cli/OutputGuard.hpp"
#include "cuetrack/cli/Values.hpp"
#include "cuetrack/platform/CommandText.hpp"

namespace cuetrack::listen {
namespace {

const char* kAbout =
    "Decodes cuetrack's serial stream (docs/serial-protocol.md): one line per track on\n"
    "stdout, or with --csv a CSV file (header + one row per track; '-' = stdout). Other\n"
    "messages (ack, error, heartbeat) go to stdout, or to stderr with --csv. The port is\n"
    "taken exclusively (lock file, flock, TIOCEXCL): a second listener is refused.";

const char* kFooter =
    "The last line gives the totals: messages by type, rejected frames, the first and\n"
    "last seq seen and the messages lost (seq gaps).\n"
    "exit codes: 0 interrupted (SIGINT/SIGTERM/SIGHUP) or --tracks reached; 1 the port\n"
    "  cannot be opened (missing, in use by another program), went away (without\n"
    "  --reconnect), or a command cannot be sent; 2 bad command line (an option other\n"
    "  than --send given twice too); 3 the CSV (or, without --csv, stdout) or the state\n"
    "  file write failed; 4 idle timeout";

// A whole number in [lo, hi], else `want` as the reason.
cli::Convert whole(long lo, long hi, const char* want, long* out) {
  return [lo, hi, want, out](const std::string& v) {
    return cli::wholeNumber(v, lo, hi, out).empty() ? std::string() : std::string(want);
  };
}

// Every option of cuetrack-listen, into *o.
void declare(cli::Command& cmd, ListenOptions* o, std::vector<std::string>* ports) {
  cmd.positionals("PORT", "the serial port (a tty, a socat pty)", ports);
  cmd.option("--baud", "N", "9600..921600 (default 115200)", [o](const std::string& v) {
    int b = 0;
    const std::string why = cli::baudRate(v, &b);
    o->baud = b;
    return why;
  });
  cmd.text("--csv", "FILE", "a CSV file instead of lines on stdout ('-' = stdout)", &o->csv);
  cmd.list("--send", "COMMAND",
           "start:X,Y,W,H, reset, stop or rate:HZ, sent once the device is up (repeatable)",
           &o->sendTexts);
  // 0 would wait for nothing.
  cmd.option("--tracks", "N", "exit after N track messages (N >= 1)",
             whole(1, 2000000000L, "expected a count >= 1", &o->maxTracks));
  cmd.option("--idle-timeout", "S", "exit with code 4 when nothing arrives for S seconds",
             whole(1, 86400, "expected seconds >= 1", &o->idleS));
  cmd.flag("--reconnect",
           "a port that goes away (unplugged): wait for it, report the seq gap (not exit 1)",
           &o->reconnect);
  cmd.option("--wait-port", "S",
             "a PORT not there yet: wait up to S seconds for it (default 5, 0: fail at once)",
             whole(0, 86400, "expected seconds >= 0", &o->waitPortS));
  cmd.text("--state", "FILE",
           "keep the last seq seen in FILE (each second, at exit): the next run reports losses",
           &o->state);
}

}  // namespace

std::string listenHelp() {
  cli::Command cmd("cuetrack-listen", kAbout, kFooter, cli::Quotes::None);
  ListenOptions o;
  std::vector<std::string> ports;
  declare(cmd, &o, &ports);
  return cmd.help();
}

ListenParse parseListenOptions(int argc, char** argv, ListenOptions* o, char* err, size_t errLen) {
  *o = ListenOptions{};
  cli::Command cmd("cuetrack-listen", kAbout, kFooter, cli::Quotes::None);
  std::vector<std::string> ports;
  declare(cmd, o, &ports);
  const cli::Command::Parsed parsed = cmd.check(argc, argv, err, errLen);
  if (parsed != cli::Command::Parsed::Run)
    return parsed == cli::Command::Parsed::Help ? ListenParse::Help : ListenParse::Error;
  if (ports.empty()) {
    std::snprintf(err, errLen, "missing PORT (see --help)");
    return ListenParse::Error;
  }
  if (ports.size() > 1) {
    std::snprintf(err, errLen, "unexpected argument '%s' (one PORT only)",
                  cli::printable(ports[1]).c_str());
    return ListenParse::Error;
  }
  if (o->sendTexts.size() > static_cast<size_t>(ListenOptions::kMaxSends)) {
    std::snprintf(err, errLen, "too many --send (at most %d)", ListenOptions::kMaxSends);
    return ListenParse::Error;
  }
  o->port = ports[0];
  o->portPath = o->port.c_str();
  o->csvPath = cmd.given("--csv") ? o->csv.c_str() : nullptr;
  o->statePath = cmd.given("--state") ? o->state.c_str() : nullptr;
  o->numSends = static_cast<int>(o->sendTexts.size());
  // The one output guard of every tool: the CSV and the state file are neither the port
  // (a regular file given as PORT) nor each other.
  cli::OutputGuard guard;
  guard.input("PORT", o->port);
  if (o->csvPath) guard.output("--csv", o->csvPath);
  if (o->statePath) guard.output("--state", o->statePath);
  if (o->statePath) guard.output("--state's temporary file", o->state + ".tmp");
  std::string clash;
  if (!guard.check(&clash)) {
    std::snprintf(err, errLen, "%s", clash.c_str());
    return ListenParse::Error;
  }
  // Every command is checked before the port is touched.
  for (int i = 0; i < o->numSends; ++i) {
    o->sends[i] = o->sendTexts[static_cast<size_t>(i)].c_str();
    if (!platform::parseCommandText(o->sends[i], static_cast<uint16_t>(i + 1), &o->commands[i], err,
                                    errLen))
      return ListenParse::Error;
  }
  return ListenParse::Run;
}

}  // namespace cuetrack::listen
