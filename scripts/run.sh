#!/usr/bin/env bash
# The one run command: installs what is missing, builds the host tools and runs the
# on-board tracker on its embedded default: the Kinect when one is plugged in,
# otherwise a generated RGB-D scene. Extra arguments go to cuetrack (see --help).
set -euo pipefail
cd "$(dirname "$0")/.."
bash scripts/setup.sh
cmake --preset host >/dev/null
cmake --build --preset host --target cuetrack
exec build/host/bin/cuetrack "$@"
