#!/usr/bin/env bash
# The setup unit's area/throughput study (docs/studies.md, "4. The setup unit: cycles against
# area"): `rastersim sweep` over setup_interval x setup_fifo_depth on the default scene and on the
# Stanford bunny (Debian's glmark2-data), and the setup unit's iCE40 LUTs and FFs at each
# setup_interval from scripts/hw-cost.sh (yosys synth_ice40; nextpnr where it fits). Writes
# OUT/{default,bunny}/sweep.csv, OUT/setup-cost.csv (one row per interval), OUT/study.csv (every
# point with its area) and OUT/cycles_vs_setup_luts.png. Synthesis results are kept in WORK and
# reused (the fastest setting takes about 20 minutes of yosys).
# Usage: scripts/setup-study.sh [--out DIR] [--work DIR] [--rastersim EXE]
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
out="$root/docs/images/studies/setup"
work="$root/build/setup-study-work"
rastersim="$root/build/rastersim"
intervals=(0 2 4 8 16 64)
depths=(1 8 16)
while [ $# -gt 0 ]; do
  case "$1" in
    --out) out="$(realpath -m "$2")"; shift 2 ;;
    --work) work="$(realpath -m "$2")"; shift 2 ;;
    --rastersim) rastersim="$(realpath "$2")"; shift 2 ;;
    *) echo "setup-study: unknown argument $1" >&2; exit 2 ;;
  esac
done
bunny=/usr/share/glmark2/models/bunny.obj
[ -f "$bunny" ] || { echo "setup-study: $bunny is missing (apt-get install glmark2-data)" >&2; exit 2; }
mkdir -p "$out" "$work"
join() { local IFS=,; echo "$*"; }

for input in default bunny; do
  if [ "$input" = bunny ]; then source=("$bunny"); else source=(--scene default); fi
  echo "setup-study: sweep $input"
  "$rastersim" sweep "${source[@]}" --vary "setup_interval=$(join "${intervals[@]}")" \
    --vary "setup_fifo_depth=$(join "${depths[@]}")" --out "$out/$input" --no-plots > /dev/null
done

for i in "${intervals[@]}"; do
  if [ ! -f "$work/i$i/hw-cost.csv" ]; then
    echo "setup-study: hw-cost of triangle_setup at setup_interval $i"
    "$root/scripts/hw-cost.sh" --setup-interval "$i" --units triangle_setup --out "$work/i$i" \
      --work "$work/i$i/work" > "$work/i$i.log" 2>&1
  fi
done

python3 - "$out" "$work" "${intervals[@]}" <<'PY'
import csv, sys
out, work, intervals = sys.argv[1], sys.argv[2], sys.argv[3:]
cost = {}
with open(f"{out}/setup-cost.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["setup_interval", "ice40_luts", "ice40_ffs", "fmax_mhz", "note"])
    for i in intervals:
        row = next(csv.DictReader(open(f"{work}/i{i}/hw-cost.csv")))
        cost[i] = row
        w.writerow([i, row["luts"], row["ffs"], row["fmax_mhz"], row["note"]])
with open(f"{out}/study.csv", "w", newline="") as f:
    w = csv.writer(f)
    w.writerow(["input", "setup_interval", "setup_fifo_depth", "cycles", "fragments_per_clock", "ice40_luts"])
    for name in ("default", "bunny"):
        for r in csv.DictReader(open(f"{out}/{name}/sweep.csv")):
            w.writerow([name, r["setup_interval"], r["setup_fifo_depth"], r["cycles"],
                        r["fragments_per_clock"], cost[r["setup_interval"]]["luts"]])
PY

# One plot per input: cycles against the setup unit's LUTs, a curve per FIFO depth, each point
# labelled with its setup_interval.
gp="$out/study.gp"
{
  echo "set terminal pngcairo size 1100,460 font ',10'"
  echo "set output 'cycles_vs_setup_luts.png'"
  echo "set datafile separator ','"
  echo "set multiplot layout 1,2 title 'Setup unit: frame cycles against iCE40 LUTs (labels: setup\\_interval; 0 = serial)'"
  echo "set xlabel 'setup unit, iCE40 LUTs (yosys synth\\_ice40)'"
  echo "set ylabel 'frame cycles'"
  echo "set logscale y"
  echo "set key top right"
  echo "set grid"
  for input in default bunny; do
    title="scene default"; [ "$input" = bunny ] && title="bunny.obj (69,666 triangles)"
    echo "set title '$title'"
    plot="plot"
    point=(6 8 2)  # circle, triangle, cross: depths that coincide stay visible
    for k in "${!depths[@]}"; do
      d=${depths[$k]}
      filter="(strcol(1) eq '$input' && \$3 == $d ? \$4 : 1/0)"
      plot+=" 'study.csv' using 6:$filter with points pt ${point[$((k % 3))]} ps 1.6 title 'setup\\_fifo\\_depth $d',"
      [ "$k" -eq 0 ] && plot+=" 'study.csv' using 6:$filter:(stringcolumn(2)) with labels offset 1.2,0.8 notitle,"
      [ "$k" -eq $((${#depths[@]} - 1)) ] && plot+=" 'study.csv' using 6:$filter:(stringcolumn(2)) with labels offset 1.2,-0.8 notitle,"
    done
    echo "${plot%,}"
  done
  echo "unset multiplot"
} > "$gp"
(cd "$out" && gnuplot study.gp)
echo "setup-study: wrote $out/study.csv, $out/setup-cost.csv and $out/cycles_vs_setup_luts.png"
