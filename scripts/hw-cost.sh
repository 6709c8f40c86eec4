#!/usr/bin/env bash
# Hardware cost on an iCE40 (yosys synth_ice40, nextpnr-ice40): LUT / FF / BRAM and Fmax per RTL
# unit and for the top (rastersim_core: the top without its frame memory, which is an external
# SRAM behind the memory port; rastersim_top: with zbuffer_memory on chip, where it fits), at the
# default profile or at the profile the flags give; writes hw-cost.csv and hw-cost.json (see
# scripts/hw_cost.py --help). Examples:
#   scripts/hw-cost.sh --out build-cost --work build-cost/work   # default profile, iCE40 HX8K
#   scripts/hw-cost.sh --width 64 --height 48 --max-memory-latency 8 --units "zbuffer_memory rastersim_top" \
#     --synthesize-memory --out build-cost-small
#   scripts/hw-cost.sh --width 320 --height 240 --z-bits 16 --units "triangle_setup z_adder" --no-pnr
set -euo pipefail
exec nice -n 5 python3 "$(cd "$(dirname "$0")" && pwd)/hw_cost.py" "$@"
