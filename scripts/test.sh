#!/usr/bin/env bash
# The one test command: installs what is missing, then builds and passes every
# test: host, host under ASan+UBSan, aarch64 and armhf under qemu-user, the fuzz
# targets for a bounded time, and the lint checks. Exits non-zero on any failure.
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh

export CTEST_PARALLEL_LEVEL=${CTEST_PARALLEL_LEVEL:-$(nproc)}
export CMAKE_BUILD_PARALLEL_LEVEL=${CMAKE_BUILD_PARALLEL_LEVEL:-$(nproc)}
FUZZ_SECONDS=${CUETRACK_FUZZ_SECONDS:-20}
start=$(date +%s)
stamp() { echo "== [$(( $(date +%s) - start ))s] $*"; }

for preset in host host-asan aarch64 armhf; do
  stamp "workflow $preset"
  cmake --workflow --preset "$preset"
done

stamp "fuzz targets (${FUZZ_SECONDS}s each)"
cmake --workflow --preset fuzz
shopt -s nullglob
fuzzers=(build/fuzz/bin/fuzz_*)
if [ ${#fuzzers[@]} -eq 0 ]; then echo "no fuzz targets built" >&2; exit 1; fi
for f in "${fuzzers[@]}"; do
  name=$(basename "$f")
  corpus="build/fuzz/corpus/$name"; mkdir -p "$corpus"
  seeds="tests/fuzz/seeds/${name#fuzz_}"
  [ -d "$seeds" ] || seeds=""
  echo "-- $name"
  "$f" -max_total_time="$FUZZ_SECONDS" -print_final_stats=1 -rss_limit_mb=2048 "$corpus" $seeds 2>&1 \
    | grep -E 'stat::number_of_executed_units|ERROR|SUMMARY|Done' || true
  test "${PIPESTATUS[0]}" -eq 0
done

stamp "all tests passed"
