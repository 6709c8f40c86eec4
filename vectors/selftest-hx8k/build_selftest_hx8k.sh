#!/usr/bin/env bash
# Builds an iCE40 HX8K bitstream of the board self-test (rastersim_selftest.v) with yosys,
# nextpnr-ice40 and icepack. RTL_DIR: the pipeline's Verilog (default ../../rtl/).
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
# OUT: where the bitstream and the logs go (default selftest_hx8k/ in this folder): rastersim_selftest.bin,
# yosys.log, nextpnr.log (utilisation and the timing report). Pins: selftest_hx8k.pcf. Exit 0 when the
# design fits the HX8K and routes; the last lines give its logic cells and Fmax.
selftest="$here/../../testbench/vectors/rastersim_selftest.v"
out="${OUT:-$here/selftest_hx8k}"
mkdir -p "$out"
cd "$here"  # $readmemh reads commands.hex and selftest.hex from here
if ! yosys -q -l "$out/yosys.log" -p "read_verilog -sv -I$here -I$rtl $selftest ${sources[*]}; \
    synth_ice40 -top rastersim_selftest -json $out/selftest.json" 2> "$out/yosys.warnings"; then
  echo "$0: yosys failed (log: $out/yosys.log)" >&2
  exit 2
fi
if ! nextpnr-ice40 --hx8k --package ct256 --pcf "$here/selftest_hx8k.pcf" --json "$out/selftest.json" \
    --asc "$out/selftest.asc" --freq 50 --timing-allow-fail --seed 1 -l "$out/nextpnr.log" 2> /dev/null; then
  echo "$0: nextpnr-ice40 failed: the design does not fit or route (log: $out/nextpnr.log)" >&2
  grep -E 'ERROR|Info: Device utilisation' -A 12 "$out/nextpnr.log" | head -n 20 >&2 || true
  exit 1
fi
icepack "$out/selftest.asc" "$out/rastersim_selftest.bin"
grep -E 'ICESTORM_LC:|ICESTORM_RAM:' "$out/nextpnr.log" | tail -n 2
grep -E "Max frequency for clock" "$out/nextpnr.log" | tail -n 1
echo "bitstream: $out/rastersim_selftest.bin"
