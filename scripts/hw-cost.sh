#!/usr/bin/env bash
# Hardware cost on an iCE40 (yosys synth_ice40, nextpnr-ice40): LUT / FF / BRAM and Fmax per RTL
# unit and for the top, at the default profile or at the profile the flags give; writes
# hw-cost.csv and hw-cost.json (see scripts/hw_cost.py --help). Example:
#   scripts/hw-cost.sh --out build-cost                       # default profile, iCE40 HX8K
#   scripts/hw-cost.sh --width 320 --height 240 --z-bits 16 --units "triangle_setup z_adder" --no-pnr
set -euo pipefail
exec nice -n 5 python3 "$(cd "$(dirname "$0")" && pwd)/hw_cost.py" "$@"
