#!/usr/bin/env bash
# Icarus Verilog 11 (-g2012) compiles every RTL unit and the top (elaboration included).
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rtl="$root/rtl"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for top in plane_register triangle_setup triangle_setup_serial triangle_setup_pipelined setup_fifo depth_bias depth_word span_bounds scanline_walker_entry scanline_walker z_adder zbuffer zbuffer_memory texture_divide texture_address texture_filter texture_memory texture_unit rastersim_core rastersim_top; do
  # -Wno-sensitivity-entire-array: the @* reductions over the stage and edge arrays are meant to
  # depend on every word; Icarus only notes it.
  if ! out=$(iverilog -g2012 -Wall -Wno-sensitivity-entire-array -I"$rtl" -s "$top" -o "$work/$top.vvp" "$rtl"/*.sv 2>&1) || [ -n "$out" ]; then
    echo "iverilog failed or warned: $top"
    echo "$out"
    status=1
  fi
done
# The pipelined setup unit (SETUP_INTERVAL >= 2) in triangle_setup (triangle_setup_pipelined).
for interval in 2 5 64; do
  if ! out=$(iverilog -g2012 -Wall -Wno-sensitivity-entire-array -I"$rtl" -s rastersim_top \
      -Prastersim_top.SETUP_INTERVAL=$interval -o "$work/top_i$interval.vvp" "$rtl"/*.sv 2>&1) || [ -n "$out" ]; then
    echo "iverilog failed or warned: rastersim_top SETUP_INTERVAL=$interval"
    echo "$out"
    status=1
  fi
done
# The texture unit (TEXTURE = 1) with both setup units.
for interval in 0 4; do
  if ! out=$(iverilog -g2012 -Wall -Wno-sensitivity-entire-array -I"$rtl" -s rastersim_top \
      -Prastersim_top.TEXTURE=1 -Prastersim_top.SETUP_INTERVAL=$interval -o "$work/top_t$interval.vvp" "$rtl"/*.sv 2>&1) || [ -n "$out" ]; then
    echo "iverilog failed or warned: rastersim_top TEXTURE=1 SETUP_INTERVAL=$interval"
    echo "$out"
    status=1
  fi
done
# The floating-point depth word and the depth bias (the Z adder's output stage).
if ! out=$(iverilog -g2012 -Wall -Wno-sensitivity-entire-array -I"$rtl" -s rastersim_top -Prastersim_top.Z_BITS=16 \
    -Prastersim_top.DEPTH_EXPONENT_BITS=4 -Prastersim_top.DEPTH_BIAS=1 -o "$work/top_depth.vvp" "$rtl"/*.sv 2>&1) || [ -n "$out" ]; then
  echo "iverilog failed or warned: rastersim_top Z_BITS=16 DEPTH_EXPONENT_BITS=4 DEPTH_BIAS=1"
  echo "$out"
  status=1
fi
[ $status -eq 0 ] && echo "rtl-iverilog: every unit compiles"
exit $status
