#!/usr/bin/env bash
# yosys 0.23: `synth` and `check -assert` (no latches, no combinational loops, no undriven or
# multiply driven nets) for every RTL unit and the top, at a small profile (16 x 8, S = 2,
# N = 16, memory latency up to 4, record FIFO of 2) so that the memories and multipliers synthesize quickly.
# Usage: rtl-yosys.sh [unit[@NAME=VALUE,...] ...]   (e.g. triangle_setup@SETUP_INTERVAL=2)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rtl="$root/rtl"
# shellcheck source=scripts/rtl-declares.sh
source "$root/scripts/rtl-declares.sh"
units=("$@")
[ ${#units[@]} -eq 0 ] && units=(plane_register triangle_setup setup_fifo depth_bias scanline_walker z_adder zbuffer zbuffer_memory rastersim_top)
declare -A values=([WIDTH]=16 [HEIGHT]=8 [SUBPIXEL_BITS]=2 [Z_BITS]=16 [MAX_MEMORY_LATENCY]=4 [MAX_SETUP_FIFO_DEPTH]=2)
status=0
for unit in "${units[@]}"; do
  top="${unit%%@*}"
  chparam=""
  for name in "${!values[@]}"; do
    if rtl_declares "$rtl" "$top" "$name"; then chparam+=" -set $name ${values[$name]}"; fi
  done
  if [ "$unit" != "$top" ]; then
    IFS=',' read -r -a extra <<< "${unit#*@}"
    for setting in "${extra[@]}"; do chparam+=" -set ${setting%%=*} ${setting#*=}"; done
  fi
  script="read_verilog -sv -I$rtl $(ls "$rtl"/*.sv | tr '\n' ' ');"
  [ -n "$chparam" ] && script+=" chparam$chparam $top;"
  script+=" synth -top $top; check -assert; stat"
  if ! out=$(yosys -q -p "$script" 2>&1); then
    echo "yosys failed: $unit"
    echo "$out" | tail -30
    status=1
  else
    echo "rtl-yosys: $unit synthesizes, check -assert clean"
  fi
done
exit $status
