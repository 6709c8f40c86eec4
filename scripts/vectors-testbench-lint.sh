#!/usr/bin/env bash
# Verilator -Wall lint of the package testbench (testbench/vectors/rastersim_vectors_tb.v) with
# the parameter files of two packages this build writes: Gouraud and flat shading (their setup
# layouts differ), each with and without the setup record. Waivers: testbench/vectors/lint_waivers.vlt
# and rtl/lint_waivers.vlt, each with its reason. Exit 1 on any warning.
# Usage: scripts/vectors-testbench-lint.sh [RASTERSIM]   (default: build/rastersim)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="${1:-$root/build/rastersim}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for shading in gouraud flat; do
  package="$work/$shading"
  "$exe" vectors --suite depth --width 16 --height 12 --shading "$shading" --rtl-path ../../rtl \
    --testbench-path ../../testbench/vectors --out "$package" > /dev/null
  for defines in "" "-DRS_NO_SETUP_RECORD"; do
    # shellcheck disable=SC2086  # defines is a list of words
    if ! out=$(verilator --lint-only -Wall --timing -I"$package" -I"$root/rtl" $defines "$root/rtl/lint_waivers.vlt" \
                 "$root/testbench/vectors/lint_waivers.vlt" --top-module rastersim_vectors_tb \
                 "$root/testbench/vectors/rastersim_vectors_tb.v" "$root"/rtl/*.sv 2>&1); then
      echo "lint failed: $shading ${defines:-(setup record read)}"
      echo "$out"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "vectors-testbench-lint: the testbench is clean"
exit $status
