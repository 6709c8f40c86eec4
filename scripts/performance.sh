#!/usr/bin/env bash
# Every figure of docs/performance.md, in one run: model speed beside Mesa (llvmpipe single-threaded,
# softpipe) on the same triangles; hardware throughput per traversal; RTL simulation speed
# (Verilator alone, co-simulation, Icarus on the same testbench); hardware cost on an iCE40.
# Usage: scripts/performance.sh [BUILD_DIR] [--no-hw-cost] [--model-only]   (default build-perf;
# results in BUILD_DIR/performance/; --model-only: the model against Mesa, at 1 and N threads, and
# nothing after). Figures on a shared machine vary with its load: the load is printed.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$root/build-perf"
hw_cost=1
model_only=0
for arg in "$@"; do
  case "$arg" in
    --no-hw-cost) hw_cost=0 ;;
    --model-only) model_only=1 ;;
    *) build="$(realpath -m "$arg")" ;;
  esac
done
out="$build/performance"
mkdir -p "$out"
cmake -S "$root" -B "$build" -DCMAKE_BUILD_TYPE=Release > /dev/null
cmake --build "$build" -j2 --target rastersim rastersim_mesa_peer > "$out/build.log"
rastersim="$build/rastersim"
peer="$build/rastersim_mesa_peer"

echo "machine: $(nproc) cores, $(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | xargs); $(uptime | sed 's/.*load/load/')"
echo

# value KEY FIELD FILE: field FIELD of the line starting with KEY.
value() { awk -v k="$1" -v f="$2" 'index($0, k) == 1 { print $f; exit }' "$3"; }

echo "## Model against Mesa: fragments per CPU second (million), depth test on, best of the repetitions"
printf '%-34s %10s %10s %10s %10s %8s %6s\n' input fragments model llvmpipe softpipe model/lp pixels
inputs=(
  "random-large|--triangles 4000 --size 50..300"
  "random-medium|--triangles 20000 --size 10..80"
  "random-small|--triangles 200000 --size 1..32"
  "scene-default|--scene default"
  "scene-shapes|--scene shapes"
  "scene-closeup|--scene closeup"
  "scene-overlap|--scene overlap"
  "scene-fan|--scene fan"
  "scene-stress|--scene stress"
  "random-60px-1024|--triangles 20000 --size 60 --width 1024 --height 1024 --cull none"
)
# The Stanford bunny from Debian's glmark2-data, when installed.
bunny=/usr/share/glmark2/models/bunny.obj
if [ -f "$bunny" ]; then inputs+=("bunny|$bunny"); else bunny=""; fi
for entry in "${inputs[@]}"; do
  name="${entry%%|*}"
  read -r -a args <<< "${entry#*|}"
  "$peer" "${args[@]}" --driver llvmpipe --repeat 10 > "$out/mesa-$name-llvmpipe.txt"
  "$peer" "${args[@]}" --driver softpipe --repeat 2 > "$out/mesa-$name-softpipe.txt"
  lp="$out/mesa-$name-llvmpipe.txt"
  sp="$out/mesa-$name-softpipe.txt"
  grep -q "^model verified    untraced render equals" "$lp" || { echo "performance: model check failed on $name" >&2; exit 1; }
  printf '%-34s %10s %10.2f %10.2f %10.2f %8s %6s\n' "$name" "$(value 'model fragments' 3 "$lp" | tr -d ,)" \
    "$(awk "BEGIN { print $(value 'model fragments' 7 "$lp") / 1e6 }")" \
    "$(awk "BEGIN { print $(value 'peer fragments' 7 "$lp") / 1e6 }")" \
    "$(awk "BEGIN { print $(value 'peer fragments' 7 "$sp") / 1e6 }")" \
    "$(value 'model / peer' 4 "$lp")" "$(value 'differing pixels' 3 "$lp")"
done
echo "(pixels: pixels whose count of covering triangles differs between the model and llvmpipe)"
echo

# The model's threaded render against llvmpipe's rasterizer threads, wall-clock, one process each.
threads=$(nproc)
echo "## Model against llvmpipe at 1 and $threads threads: fragments per second (million, wall), best of 10"
printf '%-34s %8s %10s %10s %8s\n' input threads model llvmpipe model/lp
for entry in "random-60px-1024|--triangles 20000 --size 60 --width 1024 --height 1024 --cull none" \
             "random-large|--triangles 4000 --size 50..300" "scene-closeup|--scene closeup" \
             "scene-default|--scene default" ${bunny:+"bunny|$bunny"}; do
  name="${entry%%|*}"
  read -r -a args <<< "${entry#*|}"
  for n in 1 "$threads"; do
    f="$out/threads-$name-$n.txt"
    "$peer" "${args[@]}" --driver llvmpipe --repeat 10 --threads "$n" > "$f"
    grep -q "^model verified    untraced render equals" "$f" || { echo "performance: model check failed on $name" >&2; exit 1; }
    printf '%-34s %8s %10.2f %10.2f %8s\n' "$name" "$n" "$(awk "BEGIN { print $(value 'model fragments' 4 "$f") / 1e6 }")" \
      "$(awk "BEGIN { print $(value 'peer fragments' 4 "$f") / 1e6 }")" "$(value 'model / peer wall' 5 "$f")"
  done
done
echo "(llvmpipe: LP_NUM_THREADS=0 for 1 thread, else N rasterizer threads; the model: rastersim --threads N)"
echo
[ "$model_only" = 1 ] && { echo "machine load at the end: $(uptime | sed 's/.*load/load/')"; exit 0; }

echo "## Hardware throughput (model cycles, equal to the RTL's), default profile, memory latency 2"
printf '%-16s %-5s %10s %10s %9s %9s %9s %9s %7s\n' input walk fragments cycles frag/clk "walk busy" "held" "idle" setup
for entry in "${inputs[@]}"; do
  name="${entry%%|*}"
  read -r -a args <<< "${entry#*|}"
  for traversal in bbox span; do
    f="$out/throughput-$name-$traversal.txt"
    "$rastersim" bench "${args[@]}" --traversal "$traversal" --repeat 1 > "$f"
    printf '%-16s %-5s %10s %10s %9s %9s %9s %9s %7s\n' "$name" "$traversal" "$(value 'fragments' 2 "$f" | tr -d ,)" \
      "$(value 'cycles' 2 "$f")" "$(value 'throughput' 2 "$f")" "$(value 'walker' 3 "$f" | tr -d ,)" \
      "$(value 'walker' 8 "$f" | tr -d ,)" "$(value 'walker' 13 "$f")" "$(value 'setup' 3 "$f")"
  done
done
echo "(walk busy / held / idle: shares of all cycles the walker emits, is held by the z-buffer, waits for setup;"
echo " setup: cycles from a drawn triangle's acceptance to its record; the bound is 1 fragment per clock)"
echo

echo "## RTL simulation speed"
for backend in rtl cosim; do
  "$rastersim" bench --scene default --backend "$backend" --repeat 3 > "$out/sim-$backend.txt"
done
rtl_cpu=$(value 'cpu time' 3 "$out/sim-rtl.txt")
cosim_cpu=$(value 'cpu time' 3 "$out/sim-cosim.txt")
echo "verilated top, C++ harness, scene default 640x480: $(value 'cycles' 2 "$out/sim-rtl.txt" | tr -d ,) cycles, $(value 'cycles' 6 "$out/sim-rtl.txt") cycles per cpu second"
echo "co-simulation (RTL + traced model + comparison): $(value 'cycles' 6 "$out/sim-cosim.txt") cycles per cpu second; overhead $(awk "BEGIN { printf \"%.2f\", $cosim_cpu / $rtl_cpu }")x the RTL alone (bound 1.5)"
# The same RTL on the same input under Icarus and Verilator: the test-vector package of the default
# scene (64 x 48) with its self-checking Verilog testbench; compile time excluded.
package="$root/vectors/scene-default"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
testbench=("$root/testbench/vectors/rastersim_vectors_tb.v" "$root/testbench/vectors/rastersim_memory_model.v")
iverilog -g2012 -I "$package" -I "$root/rtl" -s rastersim_vectors_tb -s perf_clock_count -o "$work/tb.vvp" \
  "${testbench[@]}" "$root/bench/perf_clock_count.v" "$root"/rtl/*.sv
verilator --binary -j 2 -O3 -Wno-fatal -Wno-lint -Wno-style --top-module rastersim_vectors_tb -I"$package" -I"$root/rtl" \
  --Mdir "$work/obj" -o tb "${testbench[@]}" "$root/bench/perf_clock_count.v" "$root"/rtl/*.sv \
  > "$work/verilator.log" 2>&1
cpu_seconds() { /usr/bin/time -f '%U %S' -o "$work/time" "$@" > "$work/log" 2>&1; awk '{ print $1 + $2 }' "$work/time"; }
icarus=$(cd "$package" && cpu_seconds vvp -n "$work/tb.vvp")
grep -q ' 0 failed' "$work/log" || { echo "performance: the Icarus testbench failed" >&2; exit 1; }
cycles=$(awk '/perf_clock_count:/ { print $2 }' "$work/log")
# Verilator's run is short: the mean of 10 runs.
total=0
for _ in 1 2 3 4 5 6 7 8 9 10; do
  t=$(cd "$package" && cpu_seconds "$work/obj/tb")
  grep -q ' 0 failed' "$work/log" || { echo "performance: the Verilator testbench failed" >&2; exit 1; }
  total=$(awk -v a="$t" -v b="$total" 'BEGIN { print a + b }')
done
best=$(awk -v t="$total" 'BEGIN { print t / 10 }')
"$rastersim" bench --scene default --width 64 --height 48 --cull back --backend rtl --repeat 5 > "$out/sim-rtl-small.txt"
echo "vectors/scene-default (64x48, $cycles testbench cycles, Verilog testbench checking every event):"
echo "  Icarus     $(awk "BEGIN { printf \"%.3g\", $cycles / $icarus }") cycles per cpu second ($icarus s)"
echo "  Verilator  $(awk "BEGIN { printf \"%.3g\", $cycles / $best }") cycles per cpu second ($best s), $(awk "BEGIN { printf \"%.0f\", $icarus / $best }")x Icarus"
echo "  Verilator with the C++ harness (rastersim bench --backend rtl, same scene and profile): $(value 'cycles' 6 "$out/sim-rtl-small.txt") cycles per cpu second"
echo

if [ "$hw_cost" = 1 ]; then
  echo "## Hardware cost, default profile, iCE40 HX8K (scripts/hw-cost.sh)"
  "$root/scripts/hw-cost.sh" --out "$out" --work "$out/hw-cost-work" 2> "$out/hw-cost.log"
  column -s, -t < "$out/hw-cost.csv"
fi
echo
echo "machine load at the end: $(uptime | sed 's/.*load/load/')"
