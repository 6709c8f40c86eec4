#!/usr/bin/env bash
# Simulates the board self-test (rastersim_selftest.v, top module rastersim_selftest_sim) with Icarus
# Verilog: the frame's cycles, both CRC-32s and the verdict the board's pins give.
# Exit 0 on "selftest: PASS", 1 on FAIL, 2 when it cannot build or a file differs from
# manifest.json. RTL_DIR: the pipeline's Verilog (default ../../rtl/).
set -euo pipefail
here="$(cd "$(dirname "$0")" && pwd)"
rtl="${RTL_DIR:-$here/../../rtl}"
shopt -s nullglob
sources=("$rtl"/*.sv "$rtl"/*.v)
if [ ${#sources[@]} -eq 0 ]; then
  echo "$0: no .sv or .v files in $rtl" >&2
  exit 2
fi
# Every file as the manifest lists it (size and CRC-32): a changed file fails here, not as
# mismatches that its expected outputs do not explain.
if command -v python3 > /dev/null; then
  python3 "$here/check_manifest.py" || exit 2
else
  echo "$0: python3 not found: the files are not checked against manifest.json" >&2
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
selftest="$here/../../testbench/vectors/rastersim_selftest.v"
if ! iverilog -g2012 -I "$here" -I "$rtl" -s rastersim_selftest_sim -o "$work/selftest.vvp" "$selftest" \
    "${sources[@]}"; then
  exit 2
fi
cd "$here"
vvp -n "$work/selftest.vvp" | tee "$work/log"
if grep -q '^selftest: PASS$' "$work/log"; then exit 0; fi
exit 1
