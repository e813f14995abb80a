#!/usr/bin/env python3
"""Runs the commands of the docs' command blocks as written, and fails naming the first
command of a block that fails (doc, line, command, exit code, its last output lines).

usage: scripts/doc-commands.py [--bin DIR] [--timeout SECONDS] [--list] [DOC...]
       (default DOC: README.md docs/first-hour.md; DIR: build/host/bin)

A command block is an indented (4 spaces) or fenced (```, ```sh, ```bash) block. Each
doc's blocks run in order in one bash, as a reader pastes them into one shell, from a
fresh folder laid out like the clone's (build/, scripts/ and CMakePresets.json linked to
the clone's; ../shared to the clone's ../shared, or to $CUETRACK_SHARED_DIR as for the
tests), with DIR on PATH and HOME a fresh folder too (what a command installs in ~ goes
there). A command that fails ends its block; the next block still runs. A block whose
lines all read `PROGRAM: ...` is shown output, not run. An identical block or simple
command already run (README.md and docs/first-hour.md share some) is not run twice.

Commands that need hardware, a network, a cross build, a person at the keyboard, or
minutes are skipped by the rules of SKIP below, each printed with its reason; a new
command in a doc runs unless a rule names it. `--show` runs under a virtual display of
its own (Xvfb) when there is one. --list prints what would run and what would be skipped.

Exit: 0 every command that ran passed; 1 one failed (named on stderr); 2 bad arguments;
77 none failed but one needs ../shared data that is absent, or a tool is missing.
"""
import argparse
import fcntl
import os
import re
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
DEFAULT_DOCS = ["README.md", "docs/first-hour.md"]

# (pattern searched in the command, why it is not run). First match wins.
SKIP = [
    (r"^git clone ", "a setup command: a fresh clone running scripts/run.sh or "
     "scripts/test.sh, and scripts/test.sh runs this check (recursion)"),
    (r"\bcuetrack-record\b", "needs a Kinect"),
    (r"--source[ =](kinect|camera)\b", "needs a Kinect or a camera"),
    (r"--wait-camera\b", "waits for a Kinect"),
    (r"/dev/tty", "needs a serial port"),
    (r"\b(ssh|scp) ", "needs a board on the network"),
    (r"\bapt(-get)? install\b|\bsystemctl\b", "installs on a board"),
    (r"--preset[ =](aarch64|armhf)\b|build/(aarch64|armhf)\b",
     "a cross build (minutes; scripts/test.sh builds and tests it)"),
    (r"\bscripts/(devset|benchmarks)\.sh\b", "a long job: the whole development set "
     "(its time is in the doc)"),
    (r"^cuetrack-bench \S+ .*--runs 10\b", "a long job: ten runs and OpenCV's slowest "
     "trackers (its time is in the doc)"),
    (r"--select\b", "needs a person to drag a box"),
]
# (pattern matching the whole command, what runs in its place, why).
RUN_AS = [
    (r"^\./scripts/run\.sh$", "cuetrack",
     "its last step; its first two, setup.sh and the build, are scripts/test.sh's too"),
]
GUI = r"--show\b"
OUTPUT_LINE = r"^[a-z][\w.-]*: "  # cuetrack: summary: ... (shown output, not a command)
SIMPLE = r"^[\w./:=,-]+( +[\w./:=,-]+)*$"  # no shell state: safe to run once for two docs


def blocks_of(path):
    """[(first line number, [(line number, text)])] of the doc's command blocks."""
    found, cur, fence, prev_blank = [], None, None, True
    for n, line in enumerate(open(path, encoding="utf-8").read().split("\n"), 1):
        if fence is not None:  # inside ```: up to the closing fence
            if line.strip().startswith("```"):
                fence, cur = None, None
            elif fence in ("", "sh", "bash", "shell"):
                cur[1].append((n, line))
            continue
        if line.strip().startswith("```"):
            fence = line.strip()[3:].strip()
            if fence in ("", "sh", "bash", "shell"):
                cur = (n + 1, [])
                found.append(cur)
            continue
        indented = line.startswith("    ") or line.startswith("\t")
        text = line[4:] if line.startswith("    ") else line[1:]
        if cur is not None and (indented or not line.strip()):
            cur[1].append((n, text))
        elif indented and prev_blank:
            cur = (n, [(n, text)])
            found.append(cur)
        else:
            cur = None
        prev_blank = not line.strip()
    return found


def complete(text):
    """Whether bash reads text as whole commands (not `if ...; then` awaiting its fi)."""
    return subprocess.run(["bash", "-n"], input=text, text=True,
                          capture_output=True).returncode == 0


def commands_of(block):
    """[(line number, command, whole)]: blank and comment-only lines out; a line that
    bash reads as unfinished (a trailing `\\`, an open `if`, a quote) runs with the
    next ones, as a shell prompts for more; whole is false for one the block leaves
    unfinished (a syntax error)."""
    out, pending = [], None
    for n, text in block:
        if pending is not None:
            pending = (pending[0], pending[1] + "\n" + text)
        elif text.strip() and not text.lstrip().startswith("#"):
            pending = (n, text.rstrip())
        if pending is not None and complete(pending[1]):
            out.append((pending[0], pending[1], True))
            pending = None
    if pending is not None:
        out.append((pending[0], pending[1].rstrip(), False))
    return out


def disposition(cmd, have_display, shared_dir):
    """('run', None) | ('run-as', (replacement, why)) | ('skip', why) | ('absent', why)."""
    for pat, why in SKIP:
        if re.search(pat, cmd):
            return "skip", why
    if re.search(GUI, cmd) and not have_display:
        return "skip", "needs a display, and Xvfb is not installed"
    try:
        words = shlex.split(cmd, comments=True)
    except ValueError:  # unbalanced quotes: bash -n names it below
        words = cmd.split()
    for word in words:
        if word.startswith("../shared/"):
            if not os.path.exists(os.path.join(shared_dir, word[len("../shared/"):])):
                return "absent", "needs %s, absent" % word
    for pat, replacement, why in RUN_AS:
        if re.fullmatch(pat, cmd.split("#")[0].strip()):
            return "run-as", (replacement, why)
    return "run", None


def start_xvfb(tmp):
    """(process, DISPLAY) of a virtual display of our own, or (None, None)."""
    if shutil.which("Xvfb") is None:
        return None, None
    fd_path = os.path.join(tmp, "display")
    # -noreset: a server that resets when its last client leaves refuses the next one
    # for a moment (cuetrack's display probe leaves just before its window connects).
    with open(fd_path, "w") as f:
        proc = subprocess.Popen(["Xvfb", "-displayfd", "1", "-screen", "0", "1280x800x24",
                                 "-nolisten", "tcp", "-noreset"], stdout=f,
                                stderr=subprocess.DEVNULL)
    end = time.time() + 30
    while time.time() < end:  # -displayfd writes the number once clients may connect
        text = open(fd_path).read()
        if text.endswith("\n") and text.strip().isdigit():
            return proc, ":" + text.strip()
        if proc.poll() is not None:
            break
        time.sleep(0.05)
    proc.kill()
    proc.wait()
    return None, None


def make_clone_like(tmp):
    """A folder laid out like the clone's, for the docs' relative paths."""
    clone = os.path.join(tmp, "cuetrack")
    os.mkdir(clone)
    for name in ("build", "scripts", "CMakePresets.json"):
        if os.path.exists(os.path.join(ROOT, name)):
            os.symlink(os.path.join(ROOT, name), os.path.join(clone, name))
    shared = os.environ.get("CUETRACK_SHARED_DIR") or os.path.join(os.path.dirname(ROOT),
                                                                    "shared")
    if os.path.isdir(shared):
        os.symlink(shared, os.path.join(tmp, "shared"))
    return clone


def script_for(plan, logdir, status):
    """The bash script that runs one doc's planned commands in order, in one shell: each
    command's output to its own log, its start, end and exit code to the status file."""
    out = ["__status=%s" % shlex.quote(status)]
    for block in plan:
        out.append("__skip=0")  # a failed command ends its block
        for n, cmd, what, arg in block:
            if what not in ("run", "run-as"):
                continue
            log = os.path.join(logdir, "%d.log" % n)
            out += ['if [ "$__skip" = 0 ]; then',
                    'echo "start %d $EPOCHREALTIME" >>"$__status"' % n,
                    "{", cmd if what == "run" else arg[0],
                    "} >%s 2>&1 </dev/null" % shlex.quote(log),
                    "__rc=$?",
                    'echo "end %d $EPOCHREALTIME $__rc" >>"$__status"' % n,
                    '[ "$__rc" = 0 ] || __skip=1',
                    "fi"]
    return "\n".join(out) + "\n"


def kill_group(proc):
    try:
        os.killpg(proc.pid, signal.SIGTERM)
    except ProcessLookupError:
        return
    end = time.time() + 5
    while time.time() < end and proc.poll() is None:
        time.sleep(0.05)
    try:
        os.killpg(proc.pid, signal.SIGKILL)  # stragglers of the group (background jobs)
    except ProcessLookupError:
        pass
    proc.wait()


def tail(path, n=8):
    try:
        lines = open(path, errors="replace").read().splitlines()
    except OSError:
        return []
    return lines[-n:]


def plan_doc(name, path, have_display, shared_dir, ran_blocks, ran_cmds, notes):
    """The doc's blocks as [[(line, command, what, arg)]]; notes gets (line, text) for
    blocks not run (shown output, already run)."""
    plan = []
    for first, block in blocks_of(path):
        cmds = commands_of(block)
        if not cmds:
            continue
        if all(re.match(OUTPUT_LINE, c) for _, c, _ in cmds):
            notes.append((first, "shown output, not run"))
            continue
        key = "\n".join(c for _, c, _ in cmds)
        if key in ran_blocks:
            notes.append((first, "the block of %s, run there" % ran_blocks[key]))
            continue
        ran_blocks[key] = "%s:%d" % (name, first)
        planned = []
        for n, c, whole in cmds:
            what, arg = disposition(c, have_display, shared_dir)
            bare = c.split("  #")[0].strip()
            if what == "run" and re.fullmatch(SIMPLE, bare):
                if bare in ran_cmds:
                    what, arg = "dup", ran_cmds[bare]
                else:
                    ran_cmds[bare] = "%s:%d" % (name, n)
            if what == "run" and not whole:
                what, arg = "bad", "not valid bash"
            planned.append((n, c, what, arg))
        plan.append(planned)
    return plan


def run_doc(plan, clone, tmp, tag, env, timeout):
    """Runs the plan; {line: (exit code or None, seconds, log path)}, and whether the
    doc ran out of time."""
    logdir = os.path.join(tmp, "logs-" + tag)
    os.mkdir(logdir)
    status = os.path.join(tmp, "status-" + tag)
    open(status, "w").close()
    script = os.path.join(tmp, "run-" + tag + ".sh")
    with open(script, "w") as f:
        f.write(script_for(plan, logdir, status))
    proc = subprocess.Popen(["bash", "--noprofile", "--norc", script], cwd=clone, env=env,
                            stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                            stderr=subprocess.DEVNULL, start_new_session=True)
    try:
        proc.wait(timeout=timeout)
        timed_out = False
    except subprocess.TimeoutExpired:
        timed_out = True
    kill_group(proc)  # and whatever the doc left running in the background
    results, begun = {}, {}
    for row in open(status).read().split("\n"):
        p = row.split()
        if len(p) == 3 and p[0] == "start":
            begun[int(p[1])] = float(p[2])
            results[int(p[1])] = (None, time.time() - float(p[2]),
                                  os.path.join(logdir, "%s.log" % p[1]))
        elif len(p) == 4 and p[0] == "end":
            n = int(p[1])
            results[n] = (int(p[3]), float(p[2]) - begun[n], results[n][2])
    return results, timed_out


def main():
    ap = argparse.ArgumentParser(description=__doc__,
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("docs", nargs="*", metavar="DOC")
    ap.add_argument("--bin", default=os.path.join(ROOT, "build/host/bin"))
    ap.add_argument("--timeout", type=float, default=240, help="seconds for one doc")
    ap.add_argument("--list", action="store_true", help="print the plan, run nothing")
    try:
        args = ap.parse_args()
    except SystemExit as e:
        return 0 if e.code == 0 else 2
    docs = args.docs or [os.path.join(ROOT, d) for d in DEFAULT_DOCS]
    for d in docs:
        if not os.path.isfile(d):
            print("doc-commands: no doc %s" % d, file=sys.stderr)
            return 2
    bindir = os.path.abspath(args.bin)
    if not args.list and not os.path.isfile(os.path.join(bindir, "cuetrack")):
        print("doc-commands: SKIPPED: no %s/cuetrack (cmake --build --preset host)" % bindir,
              file=sys.stderr)
        return 77

    # The docs name fixed paths (/tmp/ttyA): one run at a time on this machine.
    lock = open(os.path.join(tempfile.gettempdir(), "cuetrack-doc-commands.lock"), "w")
    if not args.list:
        try:
            fcntl.flock(lock, fcntl.LOCK_EX | fcntl.LOCK_NB)
        except BlockingIOError:
            print("doc-commands: waiting for another run to end", flush=True)
            fcntl.flock(lock, fcntl.LOCK_EX)
    tmp = tempfile.mkdtemp(prefix="doc-commands-")
    clone = make_clone_like(tmp)
    ran_blocks, ran_cmds, plans = {}, {}, []
    for doc in docs:
        path = os.path.abspath(doc)
        name = os.path.relpath(path, ROOT) if path.startswith(ROOT + os.sep) else doc
        notes = []
        plan = plan_doc(name, path, shutil.which("Xvfb") is not None,
                        os.path.join(tmp, "shared"), ran_blocks, ran_cmds, notes)
        plans.append((name, plan, notes))
    # A display of our own, only when a command to run needs one.
    gui = [x for _, plan, _ in plans for block in plan for x in block
           if x[2] in ("run", "run-as") and re.search(GUI, x[1])]
    xvfb, display = start_xvfb(tmp) if gui and not args.list else (None, None)
    if gui and not args.list and display is None:
        for _, plan, _ in plans:
            for block in plan:
                for k, x in enumerate(block):
                    if x in gui:
                        block[k] = (x[0], x[1], "skip", "needs a display: Xvfb did not start")
    os.mkdir(os.path.join(tmp, "home"))
    env = dict(os.environ, PATH=bindir + os.pathsep + os.environ.get("PATH", ""),
               HOME=os.path.join(tmp, "home"))
    env.pop("DISPLAY", None)
    if display:
        env["DISPLAY"] = display
    failed, absent, n_ran, n_skipped = [], [], 0, 0
    t_all = time.time()
    try:
        for i, (name, plan, notes) in enumerate(plans):
            results, timed_out = ({}, False) if args.list else run_doc(
                plan, clone, tmp, str(i), env, args.timeout)
            rows = [(n, text, []) for n, text in notes]
            for n, c, what, arg in (x for block in plan for x in block):
                c = c.replace("\n", " ")
                out = []
                if what in ("skip", "absent"):
                    n_skipped += 1
                    if what == "absent":
                        absent.append("%s:%d" % (name, n))
                    text = "skipped (%s): %s" % (arg, c)
                elif what == "dup":
                    text = "ran at %s: %s" % (arg, c)
                elif what == "bad":
                    failed.append("%s:%d: %s: %s" % (name, n, arg, c))
                    text = "FAILED (%s): %s" % (arg, c)
                elif args.list:
                    text = "runs%s%s: %s" % (
                        " as `%s` (%s)" % arg if what == "run-as" else "",
                        " under Xvfb" if re.search(GUI, c) else "", c)
                elif n not in results:
                    text = "not run (an earlier command of its block failed): %s" % c
                else:
                    rc, secs, log = results[n]
                    n_ran += 1
                    how = " as `%s` (%s)" % arg if what == "run-as" else ""
                    if rc == 0:
                        text = "ok%s, %.1f s: %s" % (how, secs, c)
                    else:
                        why = "exit %d" % rc if rc is not None else (
                            "still running after %.0f s" % args.timeout if timed_out
                            else "did not end")
                        failed.append("%s:%d: %s: %s" % (name, n, why, c))
                        text = "FAILED (%s)%s: %s" % (why, how, c)
                        out = ["    | " + line for line in tail(log)]
                rows.append((n, text, out))
            for n, text, out in sorted(rows, key=lambda r: r[0]):
                print("%s:%d: %s" % (name, n, text))
                for line in out:
                    print(line)
    finally:
        if xvfb is not None:
            xvfb.terminate()
            xvfb.wait()
        shutil.rmtree(tmp, ignore_errors=True)
    if args.list:
        return 0
    print("doc-commands: %d commands ran, %d failed, %d skipped (why: above), %.0f s"
          % (n_ran, len(failed), n_skipped, time.time() - t_all))
    for f in failed:
        print("doc-commands: FAILED %s" % f, file=sys.stderr)
    if failed:
        return 1
    if absent:
        print("doc-commands: SKIPPED: ../shared data absent for %s" % ", ".join(absent),
              file=sys.stderr)
        return 77
    return 0


if __name__ == "__main__":
    sys.exit(main())
