#!/usr/bin/env bash
# scripts/rtl-instructions.sh: the frame's cycles it prints are the model's (the cycle model's, which
# the RTL equals), and two runs count the same instructions within one part in a million (callgrind
# counts instructions, so the figure must not depend on the machine's load; a few instructions
# differ between runs: 8 in 408 million seen).
# Usage: rtl_instructions_test.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/../.." && pwd)"
rastersim="$1/rastersim"
flags=(--scene default --width 64 --height 48)
run() { "$root/scripts/rtl-instructions.sh" --rastersim "$rastersim" --top 3 "${flags[@]}"; }
first="$(run)"
second="$(run)"
echo "$first"
field() { awk -v k="$1" '$1 == k {print $2; exit}' <<<"$2"; }
model_cycles="$("$rastersim" bench --backend model --repeat 1 "${flags[@]}" | awk '/^cycles/ {print $2; exit}')"
[ "$(field cycles "$first")" = "$model_cycles" ] ||
  { echo "FAIL: cycles $(field cycles "$first"), the model's $model_cycles" >&2; exit 1; }
[ "$(field instructions "$first")" -gt 0 ] || { echo "FAIL: no instructions counted" >&2; exit 1; }
a="$(field instructions "$first")" b="$(field instructions "$second")"
awk -v a="$a" -v b="$b" 'BEGIN { d = a - b; if (d < 0) d = -d; exit !(d * 1000000 <= a) }' ||
  { echo "FAIL: two runs counted $a and $b instructions" >&2; exit 1; }
[ "$(grep -c 'Vrastersim_small' <<<"$first")" -ge 1 ] || { echo "FAIL: the verilated core is not among the top functions" >&2; exit 1; }
echo "PASS: cycles equal the model's, instruction counts repeat"
