#!/usr/bin/env bash
# Verilator -Wall lint of every RTL unit and the top, at the default profile and at a small one.
# Waivers live in rtl/lint_waivers.vlt, each with its reason. Exit 1 on any warning.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rtl="$root/rtl"
sources=("$rtl"/*.sv)
status=0
pipelined_interval='-GSETUP_INTERVAL=[1-9]'
# shellcheck source=scripts/rtl-declares.sh
source "$root/scripts/rtl-declares.sh"
for params in "" "-GWIDTH=16 -GHEIGHT=8 -GSUBPIXEL_BITS=2 -GZ_BITS=16 -GMAX_MEMORY_LATENCY=4" \
              "-GSETUP_INTERVAL=2" "-GWIDTH=16 -GHEIGHT=8 -GSUBPIXEL_BITS=2 -GZ_BITS=16 -GSETUP_INTERVAL=5" \
              "-GSETUP_INTERVAL=64" "-GTEXTURE=1" \
              "-GWIDTH=16 -GHEIGHT=8 -GSUBPIXEL_BITS=2 -GZ_BITS=16 -GSETUP_INTERVAL=0 -GTEXTURE=1" \
              "-GDEPTH_EXPONENT_BITS=3 -GDEPTH_BIAS=1" "-GPIXEL_CENTER=1 -GFILL_RULE=3 -GDEPTH_ROUNDING=1 -GCOLOR_ROUNDING=1" \
              "-GWIDTH=16 -GHEIGHT=8 -GSUBPIXEL_BITS=2 -GZ_BITS=16 -GSETUP_INTERVAL=0 -GPIXEL_CENTER=1 -GFILL_RULE=1 -GDEPTH_BIAS=1 -GDEPTH_ROUNDING=1" \
              "-GWIDTH=16 -GHEIGHT=8 -GSUBPIXEL_BITS=2 -GZ_BITS=16 -GSETUP_INTERVAL=0 -GDEPTH_EXPONENT_BITS=4 -GDEPTH_BIAS=1"; do
  for top in plane_register triangle_setup triangle_setup_serial triangle_setup_pipelined setup_fifo depth_bias depth_word span_bounds scanline_walker_entry scanline_walker z_adder zbuffer zbuffer_memory texture_divide texture_address texture_filter texture_memory texture_unit rastersim_core rastersim_top; do
    # The setup unit's schedules alone where triangle_setup builds them: the serial one at
    # SETUP_INTERVAL 0 (the default), the pipelined one at 2..64.
    case "$top" in
      triangle_setup_serial) [[ $params =~ $pipelined_interval ]] && continue ;;
      triangle_setup_pipelined) [[ $params =~ $pipelined_interval ]] || continue ;;
    esac
    unit_params=""
    for p in $params; do
      name="${p#-G}"; name="${name%%=*}"
      # Only the parameters the unit declares.
      if rtl_declares "$rtl" "$top" "$name"; then unit_params+=" $p"; fi
    done
    # shellcheck disable=SC2086
    if ! out=$(verilator --lint-only -Wall -I"$rtl" "$rtl/lint_waivers.vlt" "${sources[@]}" --top-module "$top" $unit_params 2>&1); then
      echo "lint failed: $top ${unit_params:-(default parameters)}"
      echo "$out"
      status=1
    fi
  done
done
[ $status -eq 0 ] && echo "rtl-lint: every unit is clean"
exit $status
