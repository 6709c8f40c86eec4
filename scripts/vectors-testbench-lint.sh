#!/usr/bin/env bash
# Verilator -Wall lint of the package testbench (testbench/vectors/rastersim_vectors_tb.v), memory
# model (rastersim_memory_model.v) and board self-test (rastersim_selftest.v), through the
# lint_verilator.sh that every package ships, with the parameter files of five packages this build
# writes: Gouraud and flat shading (their setup layouts differ), a package of rastersim_core with
# back-pressure (the memory model on its memory port), the floating-point depth word with a depth
# bias, and the texture unit in rastersim_core (the texture memory beside it; no self-test), each
# with and without the setup record. Waivers: the package's lint_waivers.vlt and rtl/lint_waivers.vlt
# (copies of testbench/vectors/ and rtl/), each with its reason. Exit 1 on any warning.
# Usage: scripts/vectors-testbench-lint.sh [RASTERSIM]   (default: build/rastersim)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="${1:-$root/build/rastersim}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for variant in gouraud flat core depth texture; do
  package="$work/$variant"
  case "$variant" in
    core) flags=(--memory-stall-percent 30) ;;
    depth) flags=(--depth-exponent-bits 3 --depth-bias-constant -9 --depth-bias-slope 1) ;;
    texture) flags=(--texture-unit true --texture-stall-percent 20 --top rastersim_core) ;;
    *) flags=(--shading "$variant") ;;
  esac
  "$exe" vectors --suite depth --width 16 --height 12 "${flags[@]}" --out "$package" > /dev/null
  for defines in "" "-DRS_NO_SETUP_RECORD"; do
    if ! out=$(SIM_FLAGS="$defines" "$package/lint_verilator.sh" 2>&1); then
      echo "lint failed: $variant ${defines:-(setup record read)}"
      echo "$out"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "vectors-testbench-lint: the testbench, memory model and self-test are clean"
exit $status
