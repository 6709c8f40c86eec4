#!/usr/bin/env bash
# Setup rate (docs/performance.md, "Setup rate"): the Stanford bunny (Debian's glmark2-data) and the
# default scene at every setup_interval and record FIFO depth given, with the model's cycle counts
# (equal to the RTL's, cycle for cycle). Prints a Markdown table: fragments per clock, setup busy and
# stall cycles, and the walker limit (fragments per walker-busy cycle: the rate the walker would give
# if setup were never late).
# Usage: scripts/setup-rate.sh [RASTERSIM] [--intervals "0 2 4 8 16 64"] [--depths "1 8 16"]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rastersim="$root/build/rastersim"
intervals="0 2 4 8 16 64"
depths="1 8 16"
while [ $# -gt 0 ]; do
  case "$1" in
    --intervals) intervals="$2"; shift 2 ;;
    --depths) depths="$2"; shift 2 ;;
    *) rastersim="$(realpath "$1")"; shift ;;
  esac
done
bunny=/usr/share/glmark2/models/bunny.obj
[ -f "$bunny" ] || { echo "setup-rate: $bunny is missing (apt-get install glmark2-data)" >&2; exit 2; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

echo "| input | setup_interval | setup_fifo_depth | fragments | cycles | fragments / clock | setup busy | setup stall | walker limit |"
echo "|---|---:|---:|---:|---:|---:|---:|---:|---:|"
for input in bunny default; do
  if [ "$input" = bunny ]; then source=("$bunny"); label="bunny.obj"; else source=(--scene default); label="scene default"; fi
  for i in $intervals; do
    for d in $depths; do
      "$rastersim" render "${source[@]}" --setup-interval "$i" --setup-fifo-depth "$d" --stats "$work/s.json" \
        -o "$work/c.png" > /dev/null
      python3 - "$work/s.json" "$label" "$i" "$d" <<'PY'
import json, sys
s = json.load(open(sys.argv[1]))
setup, walker = s["units"]["setup"], s["units"]["walker"]
print(f"| {sys.argv[2]} | {sys.argv[3]} | {sys.argv[4]} | {s['fragments']} | {s['cycles']} | "
      f"{s['fragments'] / s['cycles']:.3f} | {setup['busy']} | {setup['stall']} | {s['fragments'] / walker['busy']:.3f} |")
PY
    done
  done
done
