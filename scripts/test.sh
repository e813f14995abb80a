#!/usr/bin/env bash
# The one test command: installs what is missing, then builds and passes every
# test: host (with the lint checks), host under ASan+UBSan, aarch64 and armhf under
# qemu-user, and the fuzz targets for a bounded time. Exits non-zero on any failure
# and ends with each preset's ctest summary and time, and the tests passed, failed and
# skipped over all presets (a test that cannot run here, e.g. without ../shared, reports
# skipped: exit 77, never a pass). Logs: build/logs/<preset>.log.
# CUETRACK_PRESETS="host armhf" runs a subset; CUETRACK_FUZZ_SECONDS sets the fuzz time.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$(nproc)}
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}
FUZZ_SECONDS=${CUETRACK_FUZZ_SECONDS:-20}
PRESETS=${CUETRACK_PRESETS:-host host-asan aarch64 armhf}
start=$(date +%s)
stamp() { echo "== [$(( $(date +%s) - start ))s] $*"; }
mkdir -p build/logs
recap=()
passed=0 skipped=0  # ctest tests over all presets, for the closing line

# ctest counts a skipped test among the passed ("100% tests passed, 0 tests failed out
# of N") and lists it after the summary as "  12 - name (Skipped)".
count_skipped() { sed -n '/tests passed, [0-9]* tests failed/,$p' "$1" | grep -cE '^[[:space:]]+[0-9]+ - .* \(Skipped\)$' || true; }

for preset in $PRESETS; do
  stamp "workflow $preset"
  t0=$(date +%s)
  log=build/logs/$preset.log
  if ! cmake --workflow --preset "$preset" 2>&1 | tee "$log"; then
    echo "FAILED: workflow $preset (log: $log)" >&2
    grep -E '^[[:space:]]+[0-9]+ - ' "$log" >&2 || true  # ctest's list of failed tests
    exit 1
  fi
  summary=$(grep -E 'tests passed, [0-9]+ tests failed' "$log" | tail -n 1)
  if [ -z "$summary" ]; then echo "FAILED: no ctest summary in $log" >&2; exit 1; fi
  n=$(sed -nE 's/.* out of ([0-9]+).*/\1/p' <<<"$summary")
  s=$(count_skipped "$log")
  p=$(( ${n:-0} - s ))
  passed=$(( passed + p )) skipped=$(( skipped + s ))
  line="tests: $p passed, 0 failed, $s skipped"
  echo "== $preset: $line"  # ctest has just listed the skipped ones by name
  recap+=("$(printf '%-10s %5ss  %s' "$preset" $(( $(date +%s) - t0 )) "$line")")
done

stamp "fuzz targets (${FUZZ_SECONDS}s each)"
t0=$(date +%s)
cmake --workflow --preset fuzz > build/logs/fuzz.log 2>&1 || { cat build/logs/fuzz.log >&2; exit 1; }
shopt -s nullglob
fuzzers=(build/fuzz/bin/fuzz_*)
if [ ${#fuzzers[@]} -eq 0 ]; then echo "no fuzz targets built" >&2; exit 1; fi
# One fuzzer a core at a time: each runs for FUZZ_SECONDS whatever else runs.
fuzz_one() {  # fuzz_one BINARY: runs it; its exit code decides (a crash, a leak, a timeout)
  local f=$1 name corpus seeds flog frc=0
  name=$(basename "$f")
  corpus="build/fuzz/corpus/$name"; mkdir -p "$corpus"
  seeds="tests/fuzz/seeds/${name#fuzz_}"
  [ -d "$seeds" ] || seeds=""
  # The log keeps the reproducer's name.
  flog="build/fuzz/$name.log"
  "$f" -max_total_time="$FUZZ_SECONDS" -print_final_stats=1 -rss_limit_mb=2048 "$corpus" $seeds \
    >"$flog" 2>&1 || frc=$?
  echo "-- $name"
  grep -E 'stat::number_of_executed_units|ERROR|SUMMARY|Done' "$flog" || true
  if [ "$frc" -ne 0 ]; then
    tail -n 40 "$flog" >&2
    echo "fuzz: $name failed (exit $frc); full log: $flog" >&2
  fi
  return "$frc"
}
fuzz_failed=0
running=0
for f in "${fuzzers[@]}"; do
  if [ "$running" -ge "$(nproc)" ]; then
    wait -n || fuzz_failed=1
    running=$((running - 1))
  fi
  fuzz_one "$f" &
  running=$((running + 1))
done
while [ "$running" -gt 0 ]; do
  wait -n || fuzz_failed=1
  running=$((running - 1))
done
[ "$fuzz_failed" -eq 0 ] || exit 1
recap+=("$(printf '%-10s %5ss  %d fuzz targets, %ss each, no crash' fuzz $(( $(date +%s) - t0 )) ${#fuzzers[@]} "$FUZZ_SECONDS")")

echo
echo "== summary"
printf '%s\n' "${recap[@]}"
stamp "all tests passed"
# Plain closing line: every preset's ctest tests (a failure above has already exited);
# skipped tests do not fail the command, they are counted here.
echo "tests: $passed passed, 0 failed, $skipped skipped"
