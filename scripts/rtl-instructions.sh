#!/usr/bin/env bash
# RTL simulation cost in instructions (docs/performance.md, "RTL simulation speed"): runs
# `rastersim bench --backend rtl --repeat 1` once under valgrind's callgrind, which counts the
# instructions executed rather than seconds, so that the figure does not move with the machine's
# load, and prints the frame's cycles, the instructions of the timed render (the verilated model's
# construction, the memory clear, the frame and the final memories: what the bench's CPU time
# covers) and their ratio, then the functions that took the most.
# Bench flags pass through (default: --scene default, the default profile).
# Usage: scripts/rtl-instructions.sh [--rastersim PATH] [--top N] [bench flags...]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rastersim="$root/build/rastersim"
top=8
args=()
while [ $# -gt 0 ]; do
  case "$1" in
    --rastersim) rastersim="$(realpath "$2")"; shift 2 ;;
    --top) top="$2"; shift 2 ;;
    *) args+=("$1"); shift ;;
  esac
done
[ ${#args[@]} -gt 0 ] || args=(--scene default)
command -v valgrind >/dev/null || { echo "rtl-instructions: valgrind is missing (apt-get install valgrind)" >&2; exit 2; }
[ -x "$rastersim" ] || { echo "rtl-instructions: $rastersim is not built" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

if ! valgrind --tool=callgrind --callgrind-out-file="$work/callgrind.out" --toggle-collect='*render_triangles*' \
     "$rastersim" bench --backend rtl --repeat 1 "${args[@]}" >"$work/bench.txt" 2>"$work/valgrind.txt"; then
  cat "$work/bench.txt" "$work/valgrind.txt" >&2
  echo "rtl-instructions: the bench failed" >&2
  exit 1
fi
cycles="$(awk '/^cycles/ {print $2; exit}' "$work/bench.txt" | tr -d ,)"
instructions="$(awk '/I +refs:/ {gsub(",", "", $NF); print $NF; exit}' "$work/valgrind.txt")"
[ -n "$cycles" ] && [ -n "$instructions" ] || { cat "$work/bench.txt" "$work/valgrind.txt" >&2; exit 1; }
head -1 "$work/bench.txt"
echo "cycles        $cycles (the frame's)"
echo "instructions  $instructions (the timed render)"
awk -v i="$instructions" -v c="$cycles" 'BEGIN { printf "per cycle     %.0f instructions\n", i / c }'
echo "functions (instructions, share, name):"
callgrind_annotate "$work/callgrind.out" 2>/dev/null |
  perl -ne 'BEGIN { $n = shift } if (/file:function/) { $on = 1; next }
    if ($on && /^\s*([\d,]+)\s+\(\s*([\d.]+%)\)\s+(.*)$/) {
      ($count, $share, $name) = ($1, $2, $3); $name =~ s/^(\?\?\?|\S+\.(cpp|h)):// ; $name =~ s/\(.*$//;
      printf "  %15s %7s  %s\n", $count, $share, $name; exit if ++$k >= $n }' "$top"
