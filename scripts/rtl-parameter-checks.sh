#!/usr/bin/env bash
# Illegal parameters stop elaboration with a message naming the unit and the parameter: Verilator
# (lint and the builds' -Werror-USERERROR), yosys, and Icarus at time 0; legal ones pass.
# Exit 1 when a tool accepts an illegal setting or rejects a legal one.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rtl="$root/rtl"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
# unit, parameter setting, the message expected
cases=(
  "triangle_setup|SETUP_INTERVAL=1|triangle_setup: SETUP_INTERVAL must be 0 (serial) or 2..64"
  "triangle_setup|Z_BITS=12|triangle_setup: Z_BITS must be 16..32"
  "scanline_walker|SUBPIXEL_BITS=9|scanline_walker: SUBPIXEL_BITS must be 1..8"
  "zbuffer|MAX_MEMORY_LATENCY=65|zbuffer: MAX_MEMORY_LATENCY must be 1..64"
  "zbuffer_memory|MAX_MEMORY_LATENCY=0|zbuffer_memory: MAX_MEMORY_LATENCY must be 1..64"
  "z_adder|Z_GUARD_BITS=25|z_adder: Z_GUARD_BITS must be 0 (derived) or 1..24"
  "plane_register|REG_BITS=20|plane_register: need GUARD_BITS"
  "setup_fifo|ENTRIES=0|setup_fifo: ENTRIES and RECORD_BITS must be at least 1"
  "rastersim_top|MAX_SETUP_FIFO_DEPTH=0|rastersim_core: MAX_SETUP_FIFO_DEPTH must be at least 1"
  "rastersim_top|WIDTH=5000|WIDTH must be 1..4096"
)
expect_fail() {  # tool, unit, setting, message, output
  if [ "$1" = ok ]; then
    echo "FAIL: $2 with $3 was accepted; expected: $4"; status=1
  elif ! grep -qF "$4" <<<"$5"; then
    echo "FAIL: $2 with $3 stopped without the message '$4':"; echo "$5" | head -5; status=1
  fi
}
for c in "${cases[@]}"; do
  IFS='|' read -r unit setting message <<<"$c"
  name="${setting%%=*}"; value="${setting#*=}"
  # Verilator, as the builds run it (-Wno-fatal -Werror-USERERROR).
  if out=$(verilator --lint-only -Wno-fatal -Werror-USERERROR -I"$rtl" "$rtl"/*.sv --top-module "$unit" "-G$setting" 2>&1); then
    expect_fail ok "verilator: $unit" "$setting" "$message" "$out"
  else
    expect_fail failed "verilator: $unit" "$setting" "$message" "$out"
  fi
  # yosys (its elaboration of the unit alone).
  if out=$(yosys -q -p "read_verilog -sv -I$rtl $rtl/*.sv; chparam -set $name $value $unit; hierarchy -top $unit" 2>&1); then
    expect_fail ok "yosys: $unit" "$setting" "$message" "$out"
  else
    expect_fail failed "yosys: $unit" "$setting" "$message" "$out"
  fi
  # Icarus: stops at time 0.
  if iverilog -g2012 -I"$rtl" -s "$unit" "-P$unit.$setting" -o "$work/sim" "$rtl"/*.sv 2>"$work/err" && out=$(vvp -n "$work/sim" 2>&1); then
    expect_fail ok "icarus: $unit" "$setting" "$message" "$out"
  else
    expect_fail failed "icarus: $unit" "$setting" "$message" "${out:-$(cat "$work/err")}"
  fi
done
# The default parameters of every unit elaborate in all three.
for unit in plane_register triangle_setup triangle_setup_serial triangle_setup_pipelined setup_fifo scanline_walker z_adder zbuffer zbuffer_memory rastersim_top; do
  verilator --lint-only -Wno-fatal -Werror-USERERROR -I"$rtl" "$rtl"/*.sv --top-module "$unit" >/dev/null 2>&1 ||
    { echo "FAIL: verilator rejects $unit at its defaults"; status=1; }
  iverilog -g2012 -I"$rtl" -s "$unit" -o "$work/sim" "$rtl"/*.sv && vvp -n "$work/sim" >/dev/null 2>&1 ||
    { echo "FAIL: icarus rejects $unit at its defaults"; status=1; }
done
[ $status -eq 0 ] && echo "rtl-parameter-checks: every illegal setting stops with its message, the defaults elaborate"
exit $status
