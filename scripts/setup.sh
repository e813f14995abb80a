#!/usr/bin/env bash
# Installs every Debian package cuetrack needs, host and cross. Idempotent and
# non-interactive: safe to run again; skips apt when everything is present.
set -euo pipefail

HOST_PKGS=(
  build-essential cmake ninja-build pkg-config git
  ccache                             # every preset compiles through it (scripts/ccache.sh)
  libeigen3-dev catch2
  libcli11-dev                       # apps/common: every tool's command line (header-only)
  nlohmann-json3-dev                 # cuetrack-bench --json and the tests that read it (header-only)
  libopencv-dev                      # host tools only: video decoding, PNG, peer trackers
  libfreenect-dev libfreenect-bin    # Kinect driver + fakenect replay library
  libusb-1.0-0-dev
  socat                              # pseudo-terminal pairs for serial tests
  clang libclang-rt-14-dev           # libFuzzer targets
  clang-format                       # tests/lint: test_lint_format
  qemu-user                          # runs ARM test binaries; has the plugin API for icount
  g++-aarch64-linux-gnu g++-arm-linux-gnueabihf
  python3
  xvfb xdotool x11-apps              # tests/apps test_app_view: cuetrack --show/--select under
                                     # a virtual display, driven by xdotool, dumped by xwd
)
CROSS_PKGS=(
  libfreenect-dev:arm64 libusb-1.0-0-dev:arm64 libfreenect0.5:arm64 libstdc++6:arm64
  libfreenect-dev:armhf libusb-1.0-0-dev:armhf libfreenect0.5:armhf libstdc++6:armhf
)

SUDO=""  # root in CI; through sudo, `env` below carries DEBIAN_FRONTEND past sudo's env_reset
if [ "$(id -u)" != 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${HOST_PKGS[@]}" "${CROSS_PKGS[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup: all packages present"
  exit 0
fi
echo "setup: installing ${#missing[@]} packages: ${missing[*]}"

export DEBIAN_FRONTEND=noninteractive
APT_OPTS=(-y -q -o Dpkg::Options::=--force-confdef -o Dpkg::Options::=--force-confold
          -o APT::Get::Assume-Yes=true --no-install-recommends)
archs=$(dpkg --print-foreign-architectures)
for a in arm64 armhf; do
  if ! grep -qx "$a" <<<"$archs"; then $SUDO dpkg --add-architecture "$a"; fi
done
# A mirror mid-sync or a third-party list without ARM indexes fails one list,
# not the install: retry, then go on with what was fetched.
for try in 1 2 3; do
  if $SUDO apt-get update -q -o Acquire::Retries=3; then break; fi
  echo "setup: apt-get update failed (try $try), retrying" >&2; sleep 5
done
# One transaction: the multiarch libudev1 must match the host's, so apt may
# upgrade the host's libudev1/systemd in the same step; -y keeps it from asking.
$SUDO env DEBIAN_FRONTEND=noninteractive apt-get install "${APT_OPTS[@]}" "${HOST_PKGS[@]}" "${CROSS_PKGS[@]}"
echo "setup: done"
