#!/usr/bin/env bash
# The example design that is not rastersim's (examples/bbox_rasterizer, docs/verification.md):
# passes `cosim --dut ... --compare triangle`, and each of five bugs injected into a copy of it is
# caught by the same command with a first mismatch, a replay command that fails alone and a
# waveform window around the mismatch with a GTKWave save file marking it; with fewer depth
# fraction bits it passes only within its tolerance, and sampling at pixel corners only with the
# matching profile.
# Usage: example-mutants.sh RASTERSIM [COUNT [PART]]   (COUNT random frames, default 100; PART
# `design`: the example, its tolerance and its conventions; `bugs`: the five bugs; default both)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="$(cd "$(dirname "$1")" && pwd)/$(basename "$1")"
count="${2:-100}"
part="${3:-all}"
case "$part" in all | design | bugs) ;; *) echo "example-mutants: PART is design, bugs or all, not '$part'" >&2; exit 2 ;; esac
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export RASTERSIM_CACHE_DIR="$work/cache"
fail() { echo "example-mutants: $*" >&2; exit 1; }
run() {  # run DIR: the example's cosim on the design in DIR; its exit status
  local status=0
  "$exe" cosim --dut "$1/bbox_rasterizer.f" --top bbox_rasterizer --width 64 --height 48 --compare triangle \
    --count "$count" > "$1.txt" 2> "$1.err" || status=$?
  return $status
}

cp -r "$root/examples/bbox_rasterizer" original
if [ "$part" != bugs ]; then
  run original || fail "the example fails: $(grep -m1 '^frame' original.txt || tail -3 original.err)"
  echo "example-mutants: the example passes: $(tail -1 original.txt)"
fi

# name, the line as written, the line with the bug.
mutants=(
  "left_edge_bias|edge_dy[ek] < 0) ? 64'sd0 : 64'sd1;|edge_dy[ek] > 0) ? 64'sd0 : 64'sd1;"
  "box_clip|wire signed [63:0] bx1 = xb > WIDTH - 1 ? WIDTH - 1 : xb;|wire signed [63:0] bx1 = xb > WIDTH - 2 ? WIDTH - 2 : xb;"
  "truncating_divide|if (n < 0 && q * d != n) q = q - 1;|q = q;"
  "colour_order|rgb_q <= cfg_shading ? {channel[0], channel[1], channel[2]} : flat_q;|rgb_q <= cfg_shading ? {channel[2], channel[1], channel[0]} : flat_q;"
  "lequal_strict|3'd3: pass = z_q <= stored;|3'd3: pass = z_q < stored;"
)
[ "$part" = design ] && mutants=()
for m in "${mutants[@]}"; do
  IFS='|' read -r name from to <<< "$m"
  cp -r "$root/examples/bbox_rasterizer" "$name"
  python3 - "$name/bbox_rasterizer.sv" "$from" "$to" <<'PY'
import sys
path, old, new = sys.argv[1:]
text = open(path).read()
if text.count(old) != 1: sys.exit(f"{path}: '{old}' appears {text.count(old)} times")
open(path, "w").write(text.replace(old, new))
PY
  status=0
  run "$name" || status=$?
  [ "$status" -eq 1 ] || fail "mutant $name: exit $status, not 1 (not caught): $(tail -1 "$name.txt") $(tail -2 "$name.err")"
  line="$(grep -m1 '^frame ' "$name.txt")"
  replay="${line##*; replay: }"
  replay="${replay%%; waveform: *}"
  wave="${line##*; waveform: }"
  [ -s "$wave" ] || fail "mutant $name: no waveform at $wave"
  # The GTKWave save file opens the window with the primary marker at the mismatch's cycle.
  save="$wave.gtkw"
  grep -q '^\[timestart\] [0-9]' "$save" && grep -q '^\*-[0-9.]* [0-9][0-9]* ' "$save" ||
    fail "mutant $name: no GTKWave save file with a marker at $save"
  case "$line" in *"; the design's cycle "*", marked in $save; replay: "*) ;; *) fail "mutant $name: the cycle is not named: $line" ;; esac
  status=0
  eval "\"$exe\" ${replay#rastersim }" > "$name.replay.txt" 2>&1 || status=$?
  [ "$status" -eq 1 ] || fail "mutant $name: its replay exited $status: $replay"
  echo "example-mutants: $name caught: ${line:0:220}"
done
if [ "$part" = bugs ]; then
  echo "example-mutants: all ${#mutants[@]} injected bugs are caught"
  exit 0
fi
# Fewer fraction bits in the depth plane (DEPTH_DROP_BITS 4): at 64 x 48 (F = 8) the depth lies
# below the model's by at most floor(111 * 15 / 256) + 1 = 7 LSBs. Exact comparison fails; the
# tolerance of the bound passes, and the reported errors lie in [-7, 0].
drop=(--dut original/bbox_rasterizer.f --top bbox_rasterizer -G DEPTH_DROP_BITS=4 --width 64 --height 48
      --compare triangle --count "$count")
status=0
"$exe" cosim "${drop[@]}" > drop-exact.txt 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "fewer depth fraction bits passed without a tolerance (exit $status)"
grep -m1 '^frame ' drop-exact.txt | grep -q ': z: expected ' || fail "the depth difference is not named: $(grep -m1 '^frame ' drop-exact.txt)"
"$exe" cosim "${drop[@]}" --tolerance depth=7 > drop-bounded.txt 2>&1 ||
  fail "fewer depth fraction bits failed within its bound: $(grep -m1 '^frame ' drop-bounded.txt)"
line="$(grep '^compare triangle: depth error' drop-bounded.txt)"
python3 - "$line" <<'PY' || fail "the depth errors lie outside [-7, 0]: $line"
import re, sys
low, high = map(int, re.search(r"depth error \(design - model\) \d+ samples, error (-?\d+)\.\.(-?\d+)", sys.argv[1]).groups())
assert -7 <= low < 0 and high <= 0, (low, high)
PY
echo "example-mutants: fewer depth fraction bits: exact fails, depth=7 passes: ${line:0:160}"
# A design that samples pixels at their corners (PIXEL_CENTER_CORNER 1) passes only when the
# profile says so (pixel_center corner, docs/arithmetic.md section 7).
corner=(--dut original/bbox_rasterizer.f --top bbox_rasterizer -G PIXEL_CENTER_CORNER=1 --width 64 --height 48
        --compare triangle --count "$count")
status=0
"$exe" cosim "${corner[@]}" > corner-centre.txt 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "corner sampling passed against pixel_center half (exit $status)"
"$exe" cosim "${corner[@]}" --pixel-center corner > corner-corner.txt 2>&1 ||
  fail "corner sampling failed against pixel_center corner: $(grep -m1 '^frame ' corner-corner.txt)"
echo "example-mutants: corner sampling fails with pixel_center half, passes with corner: $(tail -1 corner-corner.txt)"
echo "example-mutants: the example passes$([ "$part" = all ] && echo " and all ${#mutants[@]} injected bugs are caught")"
