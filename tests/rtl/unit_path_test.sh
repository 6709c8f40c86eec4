#!/usr/bin/env bash
# cosim --unit (docs/verification.md "Checking one unit: cosim --unit"): rastersim's own setup
# unit, walker and z-buffer behind their unit interfaces (testbench/dut/rastersim_*_unit.sv) pass;
# a bug injected into a copy of each unit's RTL is caught with the triangle and field named, a
# waveform window marking the unit's cycle and a replay command that fails alone; --jobs and
# --shard give the same frames (and the same first failure); a walker that never takes a record
# is a stall naming rec_ready;
# bad usage is bad input (exit 2).
# Usage: unit_path_test.sh RASTERSIM SOURCE_DIR [PART]   (PART `interfaces`: rastersim's units and
# bad input; `bugs`: the injected bugs, the setup unit at pixel corners and the stalled walker
# template, each a build of its own; default both)
set -euo pipefail
exe="$1"
src="$(cd "$2" && pwd)"
part="${3:-all}"
case "$part" in all | interfaces | bugs) ;; *) echo "unit_path_test: PART is interfaces, bugs or all" >&2; exit 2 ;; esac
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export RASTERSIM_CACHE_DIR="$work/cache"
fail() { echo "unit_path_test: $*" >&2; exit 1; }
# The directed frames and 8 random ones of 16 triangles: a few hundred triangles.
flags=(--width 64 --height 48 --count 8)

# run NAME UNIT LIST TOP [options]: cosim --unit; its exit status.
run() {
  local name="$1" unit="$2" list="$3" top="$4" status=0
  shift 4
  "$exe" cosim --unit "$unit" --dut "$list" --top "$top" "${flags[@]}" "$@" > "$name.txt" 2> "$name.err" || status=$?
  return $status
}

# rastersim's own units pass, in each compare mode they take (the bugs' part needs the setup's run).
checks=("setup stream")
[ "$part" = bugs ] || checks+=("walker stream" "walker triangle" "zbuffer stream" "zbuffer frame")
for check in "${checks[@]}"; do
  read -r unit mode <<< "$check"
  run "own-$unit-$mode" "$unit" "$src/testbench/dut/rastersim_${unit}_unit.f" "rastersim_${unit}_unit" --compare "$mode" ||
    fail "rastersim's $unit unit failed --compare $mode: $(grep -m1 '^frame' "own-$unit-$mode.txt" || tail -3 "own-$unit-$mode.err")"
  frames="$(sed -n 's/.*: \([0-9]*\) directed and \([0-9]*\) random frames.*/\1 + \2/p' "own-$unit-$mode.txt")"
  [ -n "$frames" ] || fail "$unit --compare $mode: no frame count: $(tail -3 "own-$unit-$mode.txt")"
  grep -q "^$((frames)) passed, 0 failed$" "own-$unit-$mode.txt" || fail "$unit --compare $mode: $(tail -1 "own-$unit-$mode.txt")"
done
if [ "$part" != bugs ]; then
  grep -q "^compare triangle: depth error (design - model) [1-9][0-9]* samples, error 0\.\.0" own-walker-triangle.txt ||
    fail "the walker's fragments were not compared: $(grep '^compare' own-walker-triangle.txt)"

  # --jobs and --shard as for a design: the same report from two jobs; two shards that merge into the
  # whole run's frames.
  list="$src/testbench/dut/rastersim_setup_unit.f"
  run jobs setup "$list" rastersim_setup_unit --jobs 2 || fail "two jobs failed: $(tail -1 jobs.txt)"
  cmp -s jobs.txt own-setup-stream.txt || fail "two jobs reported otherwise: $(diff own-setup-stream.txt jobs.txt | head -5)"
  for k in 1 2; do
    run "shard-$k" setup "$list" rastersim_setup_unit --shard "$k/2" --junit "shard-$k.xml" || fail "shard $k/2 failed"
  done
  "$exe" junit-merge shard-1.xml shard-2.xml -o merged.xml > merged.txt 2>&1 || fail "the shards do not merge: $(cat merged.txt)"
  frames="$(sed -n 's/.*: \([0-9]*\) directed and \([0-9]*\) random frames.*/\1 + \2/p' own-setup-stream.txt)"
  grep -q "^merged 2 files: $((frames)) frames, 0 failed$" merged.txt || fail "the shards' frames: $(cat merged.txt), not $((frames))"
fi

# Builds of their own, run with the injected bugs (label long).
if [ "$part" != interfaces ]; then
  list="$src/testbench/dut/rastersim_setup_unit.f"
  # The setup unit built with the other sample point and a fill rule (PIXEL_CENTER, FILL_RULE): it
  # passes against the profile that says so, and not against the default one.
  corner=(-G PIXEL_CENTER=1 -G FILL_RULE=3)
  run corner setup "$list" rastersim_setup_unit "${corner[@]}" --pixel-center corner --fill-rule bottom_right ||
    fail "the setup unit at pixel corners, bottom_right failed: $(grep -m1 '^frame' corner.txt || tail -3 corner.err)"
  status=0
  run corner-default setup "$list" rastersim_setup_unit "${corner[@]}" || status=$?
  [ "$status" -eq 1 ] || fail "the setup unit at pixel corners passed against the default conventions (exit $status)"

  # The walker's installed template as it stands: a unit that never takes a record (one template:
  # the three share the harness's stall watch, and each build costs seconds).
  mkdir stuck
  cp "$src/testbench/dut/rastersim_walker_unit_template.sv" stuck/
  status=0
  "$exe" cosim --unit walker --dut stuck --top rastersim_walker_unit_template --width 64 --height 48 --count 0 --frame 0 \
    > stuck.txt 2>&1 || status=$?
  [ "$status" -eq 1 ] || fail "a stalled walker: exit $status, not 1"
  grep -q "the unit stalled: rec_ready stayed low for [0-9]* cycles with the record of triangle 0 offered" stuck.txt ||
    fail "the walker's stall is not named: $(grep -m1 '^frame' stuck.txt)"

fi

if [ "$part" != bugs ]; then
  list="$src/testbench/dut/rastersim_setup_unit.f"
  # Bad input: exit 2 with a sentence naming the problem.
  bad() {  # bad EXPECTED-TEXT ARGS...: cosim ARGS exits 2 printing EXPECTED-TEXT
    local expected="$1" status=0
    shift
    "$exe" cosim "$@" --width 64 --height 48 > bad.txt 2>&1 || status=$?
    [ "$status" -eq 2 ] || fail "cosim $*: exit $status, not 2"
    grep -q -- "$expected" bad.txt || fail "cosim $*: '$expected' not said: $(cat bad.txt)"
  }
  bad "is not setup, walker or zbuffer" --unit raster --dut "$list" --top rastersim_setup_unit
  bad "goes with --dut" --unit setup
  bad "an empty name is not setup, walker or zbuffer" --unit "" --dut "$list" --top rastersim_setup_unit
  bad "compares with stream (records in order), not --compare triangle" --unit setup --dut "$list" --top rastersim_setup_unit --compare triangle
  bad "not --compare frame" --unit walker --dut "$list" --top rastersim_setup_unit --compare frame
  bad "--tolerance applies to the walker" --unit zbuffer --dut "$list" --top rastersim_setup_unit --tolerance depth=1
fi

if [ "$part" != interfaces ]; then
  # A bug in a copy of each unit: name, unit, RTL file, the line as written, the line with the bug,
  # and the field its first mismatch names ('#' between them).
  mkdir -p bug
  mutants=(
    "top_edge_bias#setup#triangle_setup_pipelined.sv#wire bias = !owns_samples(ndy > 0, ndy < 0, dx > 0, dx < 0);#wire bias = !owns_samples(ndy > 0, ndy < 0, dx < 0, dx > 0);#: edge[0-2]_start: expected"
    "left_edge_carry#walker#plane_register.sv#along_step_carry_q[k] <= record_step[k] - step_x_in;#along_step_carry_q[k] <= record_step[k] + step_x_in;#: \(z\|color\): expected"
    "less_as_lequal#zbuffer#zbuffer.sv#rastersim_pkg::DEPTH_LESS: pass = done_z < mem_rd_depth;#rastersim_pkg::DEPTH_LESS: pass = done_z <= mem_rd_depth;#: pass: expected"
  )
  for m in "${mutants[@]}"; do
    IFS='#' read -r name unit file from to field <<< "$m"
    mkdir -p "$name/rtl" "$name/testbench/dut"
    cp "$src"/rtl/*.sv "$src"/rtl/*.vh "$name/rtl/"
    cp "$src/testbench/dut/rastersim_${unit}_unit.sv" "$src/testbench/dut/rastersim_${unit}_unit.f" "$name/testbench/dut/"
    python3 - "$name/rtl/$file" "$from" "$to" <<'PY'
import sys
path, old, new = sys.argv[1:]
text = open(path).read()
if text.count(old) != 1: sys.exit(f"{path}: '{old}' appears {text.count(old)} times")
open(path, "w").write(text.replace(old, new))
PY
    status=0
    run "$name" "$unit" "$name/testbench/dut/rastersim_${unit}_unit.f" "rastersim_${unit}_unit" --replay-dir bug || status=$?
    [ "$status" -eq 1 ] || fail "$name ($unit): exit $status, not 1 (not caught): $(tail -1 "$name.txt") $(tail -2 "$name.err")"
    line="$(grep -m1 '^frame ' "$name.txt")" || fail "$name: no failing frame reported"
    grep -q "triangle [0-9]*" <<< "$line" || fail "$name: no triangle named: $line"
    grep -q -- "$field" <<< "$line" || fail "$name: the first mismatch is not '$field': $line"
    replay="${line##*; replay: }"
    replay="${replay%%; waveform: *}"
    case "$replay" in "rastersim cosim --unit $unit --dut "*" --frame "*) ;; *) fail "$name: no replay command: $line" ;; esac
    wave="${line##*; waveform: }"
    [ -s "$wave" ] || fail "$name: no waveform at $wave"
    # The window's GTKWave save file with the primary marker at the unit's cycle the line names.
    save="$wave.gtkw"
    case "$line" in *"; the unit's cycle "*", marked in $save; replay: "*) ;; *) fail "$name: the unit's cycle is not named: $line" ;; esac
    at="${line#*"; the unit's cycle "}"
    at="${at%%,*}"
    grep -q "^\*-\?[0-9.]* $((2 * at + 9)) " "$save" && grep -q "^\[markername\] Bmismatch$" "$save" ||
      fail "$name: no marker at cycle $at's edge $((2 * at + 9)) in $save"
    status=0
    eval "\"$exe\" ${replay#rastersim }" > "$name.replay.txt" 2>&1 || status=$?
    [ "$status" -eq 1 ] || fail "$name: the replay command exited $status, not 1: $replay"
    grep -q "^0 passed, 1 failed$" "$name.replay.txt" || fail "$name: the replay did not fail its one frame: $(tail -1 "$name.replay.txt")"
    echo "unit_path_test: $name caught: ${line:0:200}"
  done

  # The first failure is the same with two jobs.
  status=0
  run top_edge_bias-jobs setup top_edge_bias/testbench/dut/rastersim_setup_unit.f rastersim_setup_unit --jobs 2 || status=$?
  [ "$status" -eq 1 ] && [ "$(grep -m1 '^frame ' top_edge_bias-jobs.txt | cut -d';' -f1)" = "$(grep -m1 '^frame ' top_edge_bias.txt | cut -d';' -f1)" ] ||
    fail "two jobs found another first failure: $(grep -m1 '^frame ' top_edge_bias-jobs.txt | cut -c1-200)"

fi
echo "unit_path_test ($part): rastersim's setup, walker and z-buffer pass; the injected bugs, the stalls and bad input are caught"
