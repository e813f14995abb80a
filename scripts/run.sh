#!/usr/bin/env bash
# The one run command: installs what is missing, builds the host tools and runs the
# on-board tracker on its embedded default: the Kinect when one is plugged in,
# otherwise a generated RGB-D scene. Extra arguments go to cuetrack (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset host >/dev/null
# Every tool the README's "Everyday use" shows, not the tests (scripts/test.sh builds those).
cmake --build --preset host --target cuetrack cuetrack-listen cuetrack-record cuetrack-synth \
  cuetrack-bench cuetrack-convert cuetrack-trackspeed cuetrack-microbench
exec build/host/bin/cuetrack "$@"
