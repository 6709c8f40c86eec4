#!/usr/bin/env bash
# Runs this package's testbench (rastersim_vectors_tb.v with rastersim_vectors_params.vh) with Icarus Verilog 11 or later.
# Exit 0 when the last line is "N passed, 0 failed"; 1 when a vector failed; 2 when it cannot build,
# a file differs from manifest.json or a plusarg is wrong (an "error:" line).
# RTL_DIR: the pipeline's Verilog (default ../../rtl/ beside this script); every .sv and .v
# file in it is compiled, with it as the include folder. SIM_FLAGS: more compiler arguments
# (e.g. -DRS_NO_SETUP_RECORD for a port without the setup record wires). Arguments go to the
# testbench: +functional (compare functionally, not cycle for cycle), +max_shown=N (mismatches
# printed, default 20), +dump=FILE (a VCD of the run; FILE relative to this folder, where the
# testbench runs), +dump_from=C and +dump_to=C (frame cycles: the VCD's window), +cycle_bound=N.
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
# shellcheck disable=SC2086  # SIM_FLAGS is a list of words
if ! iverilog -g2012 -I "$here" -I "$rtl" -s rastersim_vectors_tb ${SIM_FLAGS:-} -o "$work/tb.vvp" \
    "${testbench[@]}" "${sources[@]}"; then
  exit 2
fi
cd "$here"
vvp -n "$work/tb.vvp" "$@" | tee "$work/log"
if grep -q '^error: ' "$work/log"; then exit 2; fi
if grep -Eq '^[0-9]+ passed, 0 failed' "$work/log"; then exit 0; fi
exit 1
