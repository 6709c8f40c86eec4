#!/usr/bin/env bash
# Formal proofs of RTL units with stock yosys `sat` (docs/robustness.md). Each proof copies rtl/
# into a temporary folder, includes the unit's property files from tests/formal/ at the end of the
# module, sets small parameters (the RTL is width-generic) and runs `sat`:
#   z_adder_recurrence  plane_register: the Z adder's recurrence equals the absolute form
#                       (temporal induction: any number of steps)
#   walker_edges        scanline_walker: bbox coverage (from the span DDA) is the edge values' sign
#                       test, the edge row registers the next row's (bounded: 5 cycles)
#   walker_bounds       scanline_walker: fragments never leave the bounding box or the screen
#                       (bounded: 14 cycles)
#   zbuffer_hazard      zbuffer: input buffer order, read-after-write hazard logic, result timing,
#                       every read sees all earlier writes (bounded: 10 cycles, latencies 1..4)
# With --mutants, each proof instead runs with one deliberate bug in its unit or a unit it uses (a
# sed substitution that must apply) and must FAIL with a counterexample.
# Usage: scripts/formal.sh [--mutants] [PROOF ...]   exit 0: every proof (or every mutant's
# failure) as expected; 1 otherwise.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
mutants=0
proofs=()
for arg in "$@"; do
  case "$arg" in
    --mutants) mutants=1 ;;
    -h|--help) sed -n '2,18p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "formal.sh: unknown option $arg" >&2; exit 2 ;;
    *) proofs+=("$arg") ;;
  esac
done
all=(z_adder_recurrence walker_edges walker_bounds zbuffer_hazard)
[ ${#proofs[@]} -eq 0 ] && proofs=("${all[@]}")

# Per proof: unit | property files | parameters | sat mode | the file its mutant edits | the
# mutant's sed substitution. The unit is read with every other file of rtl/ (the units it
# instantiates), so that a mutant may edit any of them.
declare -A unit includes params mode mutated mutation
while IFS='|' read -r name u inc par m file mut; do
  unit[$name]=$u includes[$name]=$inc params[$name]=$par mode[$name]=$m mutated[$name]=$file mutation[$name]=$mut
done <<'TABLE'
z_adder_recurrence|plane_register|plane_register_recurrence.svh|REG_BITS 6 GUARD_BITS 2 OUT_BITS 3|-tempinduct|plane_register|s/: step_x ? value_q + step_x_q/: step_x ? value_q + step_y_q/
walker_edges|scanline_walker|scanline_walker_inputs.svh scanline_walker_edges.svh|WIDTH 2 HEIGHT 2 SUBPIXEL_BITS 1|-seq 5|scanline_walker|s/frag_x + 1'b1 >= span_start_q/frag_x + 1'b1 > span_start_q/
walker_bounds|scanline_walker|scanline_walker_inputs.svh scanline_walker_bounds.svh|WIDTH 4 HEIGHT 3 SUBPIXEL_BITS 1|-seq 14|span_bounds|s/({X_BITS{hi_pick_3}} \& x1)/({X_BITS{hi_pick_3}} \& (x1 + 1'b1))/
zbuffer_hazard|zbuffer|zbuffer_hazard.svh|WIDTH 2 HEIGHT 2 Z_BITS 2 MAX_MEMORY_LATENCY 4|-seq 10|zbuffer|s/(issued_q \&\& ahead_q\[head_q\])/1'b0/
TABLE

work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
status=0
for proof in "${proofs[@]}"; do
  [ -n "${unit[$proof]:-}" ] || { echo "formal.sh: unknown proof '$proof' (${all[*]})" >&2; exit 2; }
  top="${unit[$proof]}"
  dir="$work/$proof"
  mkdir -p "$dir"
  cp "$root"/rtl/*.sv "$dir/"
  if [ $mutants -eq 1 ]; then
    edited="$dir/${mutated[$proof]}.sv"
    cp "$edited" "$dir/original.sv.txt"
    sed -i "${mutation[$proof]}" "$edited"
    if cmp -s "$dir/original.sv.txt" "$edited"; then
      echo "formal.sh: the mutation of $proof no longer applies to rtl/${mutated[$proof]}.sv" >&2
      status=1
      continue
    fi
  fi
  source_file="$dir/$top.sv"
  cp "$source_file" "$dir/unit.sv.txt"
  source_file="$dir/unit.sv.txt"
  # The unit with `include lines for its properties before its last endmodule.
  lines=""
  for f in ${includes[$proof]}; do lines+="\`include \"$f\""$'\n'; done
  last="$(grep -n '^endmodule' "$source_file" | tail -1 | cut -d: -f1)"
  { head -n $((last - 1)) "$source_file"; printf '%s' "$lines"; tail -n +"$last" "$source_file"; } > "$dir/$top.sv"
  chparam=""
  set -- ${params[$proof]}
  while [ $# -gt 0 ]; do chparam+=" -chparam $1 $2"; shift 2; done
  # -defer: elaborate at the small parameters only (the defaults build 640 x 480 memories).
  script="read_verilog -defer -sv -formal -mem2reg -I$root/rtl -I$root/tests/formal $dir/*.sv;"
  script+=" hierarchy -top $top$chparam; prep -top $top -flatten; async2sync; dffunmap;"
  script+=" sat ${mode[$proof]} -prove-asserts -set-assumes -set-init-zero -show-public -verify $top"
  start=$(date +%s)
  if yosys -q -l "$dir/yosys.log" -p "$script" > /dev/null 2>&1; then proved=1; else proved=0; fi
  seconds=$(( $(date +%s) - start ))
  failed_proof=0
  grep -q "proof did fail" "$dir/yosys.log" && failed_proof=1
  if [ $mutants -eq 0 ]; then
    if [ $proved -eq 1 ]; then
      echo "formal: $proof proven ($top, ${mode[$proof]}, ${seconds} s)"
    else
      echo "formal: $proof FAILED ($top, ${mode[$proof]}, ${seconds} s); counterexample and log:"
      grep -E "ERROR|Time|\\\\" "$dir/yosys.log" | tail -80
      status=1
    fi
  else
    if [ $failed_proof -eq 1 ]; then
      echo "formal: $proof mutant caught (${mutated[$proof]}: ${mutation[$proof]}, ${seconds} s)"
    else
      echo "formal: $proof mutant NOT caught (${mutated[$proof]}: ${mutation[$proof]}, ${seconds} s)"
      tail -20 "$dir/yosys.log"
      status=1
    fi
  fi
done
exit $status
