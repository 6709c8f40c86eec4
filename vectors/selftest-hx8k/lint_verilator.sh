#!/usr/bin/env bash
# Lints this package's testbench (rastersim_vectors_tb.v, rastersim_memory_model.v) and board self-test (rastersim_selftest.v) with
# Verilator 5 -Wall and the shipped waivers (lint_waivers.vlt, and ../../rtl/lint_waivers.vlt when the RTL folder has one), each with its reason.
# Exit 0 when clean, 1 on a warning (printed), 2 when it cannot run. RTL_DIR and SIM_FLAGS
# (e.g. -DRS_NO_SETUP_RECORD): as run_verilator.sh.
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
testbench=("$here/../../testbench/vectors/rastersim_vectors_tb.v" "$here/../../testbench/vectors/rastersim_memory_model.v")
waivers=("$here/../../testbench/vectors/lint_waivers.vlt")
[ -f "$rtl/lint_waivers.vlt" ] && waivers+=("$rtl/lint_waivers.vlt")
command -v verilator > /dev/null || { echo "$0: verilator not found" >&2; exit 2; }
status=0
# shellcheck disable=SC2086  # SIM_FLAGS is a list of words
if ! verilator --lint-only -Wall --timing -I"$here" -I"$rtl" ${SIM_FLAGS:-} "${waivers[@]}" --top-module rastersim_vectors_tb \
    "${testbench[@]}" "${sources[@]}"; then
  status=1
fi
# The board self-test as yosys reads it (SYNTHESIS hides its simulation wrapper).
if ! verilator --lint-only -Wall -DSYNTHESIS -I"$here" -I"$rtl" "${waivers[@]}" --top-module rastersim_selftest \
    "$here/../../testbench/vectors/rastersim_selftest.v" "${sources[@]}"; then
  status=1
fi
[ $status -eq 0 ] && echo "lint: clean"
exit $status
