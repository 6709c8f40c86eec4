#!/usr/bin/env bash
# Installs the Debian 12 packages rastersim builds and tests with. Idempotent; run as root.
set -euo pipefail
packages=(
  build-essential cmake pkg-config git
  libgtest-dev libbenchmark-dev
  libopenimageio-dev openimageio-tools libpng-dev
  nlohmann-json3-dev libcli11-dev libtinyobjloader-dev
  verilator libsystemc-dev iverilog yosys
  libosmesa6-dev nextpnr-ice40 fpga-icestorm
  gnuplot-nox
  python3-dev python3-pybind11 python3-numpy python3-pytest  # the Python module and its tests
  python3-yaml  # scripts/check-fusesoc-core.sh reads rastersim.core
  glmark2-data  # the Stanford bunny (bunny.obj) for the real-mesh benchmark
)
missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all packages present"
  exit 0
fi
echo "install-deps: installing ${missing[*]}"
if [ "$(id -u)" -ne 0 ]; then SUDO=sudo; else SUDO=; fi
$SUDO apt-get update -q
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
