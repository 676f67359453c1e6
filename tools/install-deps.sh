#!/usr/bin/env bash
# Installs every build and run dependency of tribo from Debian 12 packages.
# Skips apt entirely when all packages are already present (no network needed then).
set -euo pipefail
packages=(
  cmake g++ make pkg-config git
  libeigen3-dev libsuitesparse-dev libhypre-dev libfftw3-dev libsundials-dev libceres-dev
  libtomlplusplus-dev libcli11-dev nlohmann-json3-dev libopenblas-openmp-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  python3 python3-matplotlib python3-numpy python3-pandas python3-dev pybind11-dev
  python3-venv python3-pip python3-setuptools python3-wheel
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "ok installed" || missing+=("$p")
done
if ((${#missing[@]})); then
  echo "tribo: installing ${missing[*]}"
  SUDO=""; [ "$(id -u)" -eq 0 ] || SUDO="sudo"
  $SUDO apt-get update -qq
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
fi
