#!/usr/bin/env bash
# Builds this build's .deb with cpack and checks what a board would get: the control
# fields (architecture, dependencies found by dpkg-shlibdeps, the conffile), the files
# (programs, service, settings, udev rule, protocol sources), and that the packaged
# cuetrack runs (through the build's emulator on a cross build), both on the synthetic
# scene and with the service's own command line from the packaged settings.
#   check_deb.sh BUILD_DIR DEB_ARCH WITH_FREENECT(ON|OFF) [EMULATOR...]
set -euo pipefail
[ $# -ge 3 ] || { echo "usage: check_deb.sh BUILD_DIR DEB_ARCH ON|OFF [EMULATOR...]" >&2; exit 1; }
build=$(cd "$1" && pwd) arch=$2 freenect=$3
shift 3
emu=("$@")
fail() { echo "check_deb: $*" >&2; exit 1; }

work=$(mktemp -d "${TMPDIR:-/tmp}/cuetrack-deb.XXXXXX")
trap 'rm -rf "$work"' EXIT
cpack --config "$build/CPackConfig.cmake" -B "$work/out" >"$work/cpack.log" 2>&1 ||
  { cat "$work/cpack.log" >&2; fail "cpack failed"; }
deb=$(find "$work/out" -maxdepth 1 -name "cuetrack_*_$arch.deb" | head -n 1)
[ -n "$deb" ] || fail "no cuetrack_*_$arch.deb in $(ls "$work/out")"
echo "package: $(basename "$deb")"

field() { dpkg-deb -f "$deb" "$1"; }
[ "$(field Package)" = cuetrack ] || fail "Package is '$(field Package)'"
[ "$(field Architecture)" = "$arch" ] || fail "Architecture is '$(field Architecture)', not $arch"
deps=$(field Depends)
echo "Depends: $deps"
want_deps=(libc6 libstdc++6)
[ "$freenect" = ON ] && want_deps+=(libfreenect0.5 libusb-1.0-0)
dep_names=$(tr ',' '\n' <<<"$deps" | sed 's/^ *//; s/[ (].*//')
for d in "${want_deps[@]}"; do
  grep -qxF "$d" <<<"$dep_names" || fail "Depends lacks $d"
done

dpkg-deb -e "$deb" "$work/control"
grep -qx /etc/default/cuetrack "$work/control/conffiles" || fail "/etc/default/cuetrack is not a conffile"
for script in preinst postinst prerm postrm; do
  [ -x "$work/control/$script" ] || fail "$script missing or not executable"
  sh -n "$work/control/$script" || fail "$script is not valid sh"
done

dpkg-deb -x "$deb" "$work/root"
r=$work/root
want_files=(usr/bin/cuetrack usr/bin/cuetrack-listen usr/lib/systemd/system/cuetrack.service
            etc/default/cuetrack usr/share/cuetrack/protocol/cuetrack_proto.h
            usr/share/cuetrack/protocol/cuetrack_proto.c
            usr/share/cuetrack/protocol/example/fc_link.h
            usr/share/cuetrack/protocol/example/fc_link.c usr/share/doc/cuetrack/copyright
            usr/share/doc/cuetrack/README.md usr/share/doc/cuetrack/docs/first-hour.md
            usr/share/doc/cuetrack/docs/serial-protocol.md usr/share/doc/cuetrack/docs/mavlink.md
            usr/lib/udev/rules.d/52-cuetrack-serial.rules)
[ "$freenect" = ON ] && want_files+=(usr/bin/cuetrack-record usr/lib/udev/rules.d/51-cuetrack-kinect.rules)
for f in "${want_files[@]}"; do
  [ -e "$r/$f" ] || fail "package lacks /$f"
done
# Every doc a packaged program names (its --help, its closing "next:" line) is packaged
# where that name finds it: under /usr/share/doc/cuetrack, as in the clone.
named=$(grep -ahoE 'docs/[A-Za-z0-9_-]+\.md' "$r"/usr/bin/* | sort -u)
[ -n "$named" ] || fail "no packaged program names a doc (docs/NAME.md): the check is blind"
for d in $named; do
  [ -e "$r/usr/share/doc/cuetrack/$d" ] || fail "a packaged program names $d, not packaged"
done
# The unit starts the installed path; no build-tree path leaked into any text file.
grep -q '^ExecStart=/usr/bin/cuetrack ' "$r/usr/lib/systemd/system/cuetrack.service" ||
  fail "the service does not start /usr/bin/cuetrack"
if grep -rlI -- "$build" "$r" >/dev/null; then fail "a packaged file names the build folder"; fi
# systemd's own check of the unit (every key known, in its section), where systemd is.
if command -v systemd-analyze >/dev/null; then
  sed "s|^ExecStart=/usr/bin/cuetrack |ExecStart=$r/usr/bin/cuetrack |" \
    "$r/usr/lib/systemd/system/cuetrack.service" >"$work/cuetrack.service"
  verify=$(systemd-analyze verify "$work/cuetrack.service" 2>&1) || fail "systemd-analyze: $verify"
  [ -z "$verify" ] || fail "systemd-analyze: $verify"
else
  echo "systemd-analyze not found: the unit's keys are not checked"
fi

# The packaged program tracks (the embedded synthetic scene).
out=$("${emu[@]}" "$r/usr/bin/cuetrack" --frames 3 --quiet) || fail "packaged cuetrack failed ($?)"
[ "$(grep -c '^track seq=' <<<"$out")" -eq 3 ] || fail "packaged cuetrack printed: $out"

# The service's command line, expanded as systemd does from the packaged settings: the
# line is split at spaces first; then a word that is ${X} becomes exactly one argument
# (empty if X is), a word that is $X becomes X's words (none if X is empty).
declare -A setting=()
while IFS= read -r kv; do
  k=${kv%%=*} v=${kv#*=}
  v=${v#\"} v=${v%\"}  # EnvironmentFile strips one pair of double quotes
  setting[$k]=$v
done < <(grep -E '^[A-Z_]+=' "$r/etc/default/cuetrack")
for k in "${!setting[@]}"; do
  [ "$k" = CUETRACK_EXTRA_ARGS ] || [ -n "${setting[$k]}" ] || fail "setting $k is empty"
done
# Run it the way a board would, but on a pseudo-terminal pair in place of the UART.
# Without socat (scripts/setup.sh installs it) this part cannot run: exit 77, which ctest
# reports as skipped (SKIP_RETURN_CODE), not as a pass.
command -v socat >/dev/null ||
  { echo "SKIPPED: socat not found: the service's command line is not run" >&2; exit 77; }
setting[CUETRACK_SERIAL]=$work/ttyA
read -ra words <<<"$(sed -n 's/^ExecStart=//p' "$r/usr/lib/systemd/system/cuetrack.service")"
args=()
for w in "${words[@]}"; do
  if [[ "$w" =~ ^\$\{([A-Z_]+)\}$ ]]; then
    k=${BASH_REMATCH[1]}
    [ -n "${setting[$k]+set}" ] || fail "the unit uses \${$k}, which the settings file lacks"
    args+=("${setting[$k]}")
  elif [[ "$w" =~ ^\$([A-Z_]+)$ ]]; then
    k=${BASH_REMATCH[1]}
    [ -n "${setting[$k]+set}" ] || fail "the unit uses \$$k, which the settings file lacks"
    read -ra split <<<"${setting[$k]}"
    args+=("${split[@]}")
  else
    [[ "$w" != *'$'* ]] || fail "unexpanded word in ExecStart: $w"
    args+=("$w")
  fi
done
args[0]=$r/usr/bin/cuetrack
echo "service command: ${args[*]}"

# Without a Kinect the service must keep the line alive: HEARTBEATs flagged no-camera
# reach the other end, and a STOP from there ends it with exit 0. (With a Kinect plugged
# in, tracks come instead, idle until a START.)
socat_pid="" service_pid="" listen_pid=""
# Whatever happens, nothing started here outlives the test (ctest would wait for it).
trap 'kill $listen_pid $service_pid $socat_pid 2>/dev/null; rm -rf "$work"' EXIT
# Each wait polls for what it waits for against a deadline, generous for qemu on a loaded
# machine: done as soon as it is there, a failure naming it when it never comes.
readonly kDeadlineS=60
wait_for() {  # wait_for WHAT TEST...: polls TEST until it holds or kDeadlineS pass
  local what=$1 end=$(( $(date +%s) + kDeadlineS ))
  shift
  until "$@" 2>/dev/null; do
    [ "$(date +%s)" -lt "$end" ] || fail "no $what within ${kDeadlineS} s"
    sleep 0.05
  done
}
socat "PTY,raw,echo=0,link=$work/ttyA" "PTY,raw,echo=0,link=$work/ttyB" >/dev/null 2>&1 &
socat_pid=$!
wait_for "pseudo-terminal pair from socat" test -e "$work/ttyB"
listen=$r/usr/bin/cuetrack-listen
if [ "$freenect" != ON ]; then  # a build without the Kinect driver refuses to wait
  rc=0
  "${emu[@]}" "${args[@]}" >/dev/null 2>"$work/service.err" || rc=$?
  [ "$rc" -eq 1 ] && grep -q 'no Kinect driver' "$work/service.err" ||
    fail "without libfreenect, --wait-camera gave exit $rc: $(cat "$work/service.err")"
  echo "check_deb: ok"
  exit 0
fi
"${emu[@]}" "${args[@]}" >"$work/service.out" 2>"$work/service.err" &
service_pid=$!
# The listener runs until interrupted: hear the service's first message (a HEARTBEAT, or a
# track with a Kinect), then send the STOP and hear its ACK.
hear() {  # hear FILE WHAT REGEX [LISTEN-ARGS...]: a listener until a line of FILE matches
  local file=$1 what=$2 regex=$3
  shift 3
  "${emu[@]}" "$listen" "$work/ttyB" "$@" >"$file" 2>/dev/null &
  listen_pid=$!
  wait_for "$what" grep -qE "$regex" "$file"
  kill -INT "$listen_pid" 2>/dev/null || true  # it may have ended with the port
  wait "$listen_pid" || true
  listen_pid=""
}
hear "$work/heard-first.txt" "message from the service" '^(heartbeat|track) '
hear "$work/heard-stop.txt" "ACK for the STOP" '^ack seq=[0-9]* stop' --send stop
cat "$work/heard-first.txt" "$work/heard-stop.txt" >"$work/heard.txt"
rc=0
timeout 30 tail --pid="$service_pid" -f /dev/null || fail "cuetrack did not end after STOP"
wait "$service_pid" || rc=$?
service_pid=""
echo "exit $rc; stderr: $(cat "$work/service.err")"
echo "heard: $(head -c 300 "$work/heard.txt")"
[ "$rc" -eq 0 ] || fail "the service's command line ended with exit $rc: $(cat "$work/service.err")"
grep -q '^ack seq=[0-9]* stop' "$work/heard.txt" || fail "no ACK for the STOP"
if ! grep -q '^track ' "$work/heard.txt"; then  # no camera here
  grep -q '^heartbeat .* no-camera' "$work/heard.txt" || fail "no HEARTBEAT flagged no-camera"
  grep -q 'waiting for it (--wait-camera)' "$work/service.err" ||
    fail "no one-line report of the missing camera: $(cat "$work/service.err")"
fi
echo "check_deb: ok"
