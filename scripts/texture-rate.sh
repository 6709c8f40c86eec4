#!/usr/bin/env bash
# Texture unit rate (docs/performance.md, "Texture unit"): fragments per clock of the textured
# built-in scene (floor) and the default scene with and without the profile's texture unit, at
# z-buffer and texture memory latency 1 and the default pipelined setup, and the textured one's
# share of the untextured rate (the issue's bar: at least 0.9). Model cycle counts (the cycle model).
# Usage: scripts/texture-rate.sh [RASTERSIM] [--latencies "1 4 16"]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rastersim="$root/build/rastersim"
latencies="1"
while [ $# -gt 0 ]; do
  case "$1" in
    --latencies) latencies="$2"; shift 2 ;;
    *) rastersim="$(realpath "$1")"; shift ;;
  esac
done
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

rate() {  # scene texture_unit latency -> "fragments cycles"
  "$rastersim" render --scene "$1" --texture-unit "$2" --memory-latency "$3" --texture-latency "$3" \
    --stats "$work/s.json" > /dev/null
  python3 -c 'import json,sys; s=json.load(open(sys.argv[1])); print(s["fragments"], s["cycles"])' "$work/s.json"
}

echo "| scene | latency | fragments | cycles without | cycles with the texture unit | fragments / clock without | with | share |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|"
for scene in floor default; do
  for l in $latencies; do
    read -r f0 c0 < <(rate "$scene" false "$l")
    read -r f1 c1 < <(rate "$scene" true "$l")
    python3 -c 'import sys; f0,c0,f1,c1=map(int,sys.argv[3:]); print(f"| {sys.argv[1]} | {sys.argv[2]} | {f1} | {c0} | {c1} | {f0/c0:.3f} | {f1/c1:.3f} | {(f1/c1)/(f0/c0):.3f} |")' \
      "$scene" "$l" "$f0" "$c0" "$f1" "$c1"
  done
done
