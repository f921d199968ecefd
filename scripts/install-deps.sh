#!/usr/bin/env bash
# Installs the Debian packages ivv needs, and only those that are missing.
# Called by `make`; safe to run repeatedly (a no-op once everything is present).
set -euo pipefail

packages=(
  cmake make g++ pkg-config clang-format
  clang libclang-rt-14-dev           # make fuzz: libFuzzer targets (fuzz/)
  libboost1.81-dev libboost-math1.81-dev  # odeint, math, multiprecision; 1.81: its uBLAS
                                          # (odeint rosenbrock4) compiles as C++20, 1.74 does not
  libeigen3-dev
  libceres-dev                        # calibration (ivv calibrate): least squares, covariance
  libgsl-dev                          # odeiv2, integration
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libsundials-dev                     # CVODE, ARKODE: peers in the speed studies and `ivv bench`
  libfccp-dev                         # fast-cpp-csv-parser
  libcli11-dev nlohmann-json3-dev libtomlplusplus-dev
  libmuparser-dev                     # expression contact laws
  gnuplot-nox                         # report plots (SVG terminal)
  chromium fonts-dejavu-core          # the report's rendering test (headless), with a font
  zlib1g-dev                          # which decodes its screenshots
  openmpi-bin libopenmpi-dev          # `mpirun -np N ivv sweep` (and its 2-rank test)
  pybind11-dev python3-dev python3-numpy  # the Python module `import ivv` (python/)
  python3-pytest                      # its tests
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "install-deps: installing ${missing[*]}" >&2
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
