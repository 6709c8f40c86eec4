#!/usr/bin/env bash
# The library's cost per call (docs/performance.md, "The model as a library"): renders the default
# scene through the DPI-C path (examples/dpi/render_tb.sv under Verilator: every triangle submitted,
# every fragment read back through rastersim_dpi) and through the CLI's model backend, both from an
# installed tree, and prints the best of REPEATS wall times and their ratio.
# Usage: library-bench.sh BUILD_DIR [REPEATS]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: library-bench.sh BUILD_DIR [REPEATS]}" && pwd)"
repeats="${2:-5}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
prefix="$work/prefix"
cmake --install "$build" --prefix "$prefix" > /dev/null
"$prefix/bin/rastersim" render --scene default --dump-tri "$work/default.tri" > /dev/null
cmake -S "$prefix/share/doc/rastersim/examples/dpi" -B "$work/dpi" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log" 2>&1 || { tail -20 "$work/configure.log"; exit 1; }
cmake --build "$work/dpi" --target render_tb > "$work/build.log" 2>&1 || { tail -20 "$work/build.log"; exit 1; }

best() {  # prints the best wall time in seconds of REPEATS runs of the command
  local best=""
  for _ in $(seq "$repeats"); do
    local start end
    start=$(date +%s.%N)
    "$@" > "$work/out.txt"
    end=$(date +%s.%N)
    best=$(python3 -c "t = $end - $start; b = '$best'; print(min(t, float(b)) if b else t)")
  done
  echo "$best"
}
dpi=$(best "$work/dpi/render_tb" +tri="$work/default.tri")
dpi_line=$(grep "render_tb: [0-9]" "$work/out.txt")
cli=$(best "$prefix/bin/rastersim" render "$work/default.tri")
cli_line=$(grep "^fragments\|^cycles" "$work/out.txt" | tr '\n' ' ')
python3 - "$dpi" "$cli" <<PY
import sys
dpi, cli = map(float, sys.argv[1:3])
print(f"default scene ($repeats runs each, best wall time):")
print(f"  DPI-C path (render_tb, every fragment read back): {dpi:.3f} s   [$dpi_line]")
print(f"  CLI model backend (rastersim render):                 {cli:.3f} s   [$cli_line]")
print(f"  ratio DPI / CLI: {dpi / cli:.2f}")
PY
