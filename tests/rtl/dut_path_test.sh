#!/usr/bin/env bash
# cosim --dut (docs/verification.md): rastersim's own core behind the verification interface
# (testbench/dut/rastersim_dut.sv) passes cycle, stream, triangle and frame, and cycle mode's report
# and coverage equal cosim's without --dut; so does the core with the memory port
# (rastersim_dut_memory.sv, the harness's memory behind it), also with a memory that refuses reads;
# --threads 2 (the model beside the design) reports the same; a latency other than the profile's fails cycle mode on a retirement cycle; the same core with its depth
# test `<` written `<=` fails frame mode at the default --count, and the printed replay command
# fails alone; a design that never takes a triangle is a clear stall error naming cmd_ready; bad
# file lists are bad input (exit 2) naming the file and line; --wave writes the design's waveform.
# Usage: dut_path_test.sh RASTERSIM SOURCE_DIR
set -euo pipefail
exe="$1"
src="$(cd "$2" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export RASTERSIM_CACHE_DIR="$work/cache"
fail() { echo "dut_path_test: $*" >&2; exit 1; }
flags=(--width 64 --height 48)

# The design's micro-architecture as parameters, the model's as the profile's keys (with --dut they
# are not varied between frames).
own=(--dut "$src/testbench/dut/rastersim_dut.f" --top rastersim_dut -G TRAVERSAL_SPAN=0 -G MEMORY_LATENCY=5
     --traversal bbox --memory-latency 5)
for mode in cycle stream triangle frame; do
  "$exe" cosim "${own[@]}" "${flags[@]}" --count 20 --compare "$mode" --coverage "own-$mode.json" > "own-$mode.txt" 2> "own-$mode.err" || fail "rastersim's core failed --compare $mode: $(grep -E '^frame|passed' "own-$mode.txt" | head -3)"
  grep -q "^47 passed, 0 failed$" "own-$mode.txt" || fail "--compare $mode: $(tail -1 "own-$mode.txt")"
  [ "$mode" = cycle ] && continue
  grep -q "^compare $mode: depth error (design - model) [0-9]* samples, error 0\.\.0: 0 x" "own-$mode.txt" || fail "no error distribution for $mode"
  # The same histogram in the JSON: every difference 0.
  python3 - "own-$mode.json" "$mode" <<'PY' || fail "no histogram in the coverage JSON for $mode"
import json, sys
compare = json.load(open(sys.argv[1]))["compare"]
assert compare["mode"] == sys.argv[2] and list(compare["depth_error"]) == ["0"] and compare["depth_error"]["0"] > 0, compare
assert list(compare["color_error"]) == ["0"], compare
PY
done

# Cycle mode through the interface reports what cosim reports of rastersim_top: the same frames,
# table, summary and coverage JSON.
"$exe" cosim "${flags[@]}" --traversal bbox --memory-latency 5 --setup-fifo-depth 8 --count 20 --coverage top.json > top.txt 2> top.err ||
  fail "cosim of rastersim_top failed: $(tail -1 top.txt)"
cmp -s top.txt own-cycle.txt || fail "cycle mode's report differs from cosim's: $(diff top.txt own-cycle.txt | head -5)"
cmp -s top.json own-cycle.json || fail "cycle mode's coverage JSON differs from cosim's"
# --threads 2 runs each frame's model beside the design: the same report and coverage.
"$exe" cosim "${own[@]}" "${flags[@]}" --count 20 --compare cycle --threads 2 --coverage threads.json > threads.txt 2> threads.err ||
  fail "--threads 2 failed: $(tail -1 threads.txt)"
cmp -s threads.txt own-cycle.txt || fail "--threads 2 changed the report: $(diff own-cycle.txt threads.txt | head -5)"
cmp -s threads.json own-cycle.json || fail "--threads 2 changed the coverage JSON"
# The memory port: the same report from the harness's memory, no read-back.
memory=(--dut "$src/testbench/dut/rastersim_dut.f" --top rastersim_dut_memory -G TRAVERSAL_SPAN=0 -G MEMORY_LATENCY=5
        --traversal bbox --memory-latency 5)
for mode in cycle stream triangle frame; do
  "$exe" cosim "${memory[@]}" "${flags[@]}" --count 20 --compare "$mode" > "memory-$mode.txt" 2> "memory-$mode.err" ||
    fail "the core with the memory port failed --compare $mode: $(grep -E '^frame|passed' "memory-$mode.txt" | head -3)"
  grep -q "^47 passed, 0 failed$" "memory-$mode.txt" || fail "memory port, --compare $mode: $(tail -1 "memory-$mode.txt")"
done
cmp -s top.txt memory-cycle.txt || fail "the memory port's cycle report differs from cosim's: $(diff top.txt memory-cycle.txt | head -5)"
# A memory that refuses 30 % of the reads: the model delays each refused read, so cycle mode passes
# only when the harness refuses exactly those (a harness that never refused would retire early).
"$exe" cosim "${memory[@]}" "${flags[@]}" --count 20 --compare cycle --memory-stall-percent 30 > stalls.txt 2> stalls.err ||
  fail "the memory port with refusals failed cycle mode: $(grep -E '^frame|passed' stalls.txt | head -3)"
grep -q "^47 passed, 0 failed$" stalls.txt || fail "refusals: $(tail -1 stalls.txt)"
# A design that keeps its buffers has no memory to refuse: bad input.
status=0
"$exe" cosim "${own[@]}" "${flags[@]}" --count 1 --memory-stall-percent 30 > keeps.txt 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "memory_stall_percent 30: rastersim_dut keeps its buffers" keeps.txt ||
  fail "refusals for a design without the memory port: exit $status: $(cat keeps.txt)"

# A design whose memory latency is not the profile's (the build above, latency 5, against a
# profile's 4): the first retirement a cycle late.
status=0
"$exe" cosim --dut "$src/testbench/dut/rastersim_dut.f" --top rastersim_dut -G TRAVERSAL_SPAN=0 -G MEMORY_LATENCY=5 \
  --traversal bbox --memory-latency 4 "${flags[@]}" --count 2 --compare cycle > latency.txt 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "a latency of 5 against the profile's 4 passed cycle mode (exit $status)"
grep -m1 '^frame ' latency.txt | grep -q "retirement cycle: expected cycle \([0-9]*\), the design gave cycle" ||
  fail "the late retirement is not named: $(grep -m1 '^frame ' latency.txt)"
expected=$(grep -m1 '^frame ' latency.txt | sed -n 's/.*expected cycle \([0-9]*\), the design gave cycle \([0-9]*\).*/\1 \2/p')
[ "$(echo "$expected" | awk '{print $2 - $1}')" = 1 ] || fail "the retirement is not one cycle late: $expected"

# The depth test's < written <=.
mkdir -p bug/rtl bug/testbench/dut
cp "$src"/rtl/*.sv "$src"/rtl/*.vh "$src"/rtl/rastersim.f bug/rtl/
cp "$src"/testbench/dut/rastersim_dut*.sv "$src"/testbench/dut/rastersim_dut.f bug/testbench/dut/
sed -i 's/rastersim_pkg::DEPTH_LESS: pass = done_z < mem_rd_depth;/rastersim_pkg::DEPTH_LESS: pass = done_z <= mem_rd_depth;/' bug/rtl/zbuffer.sv
cmp -s bug/rtl/zbuffer.sv "$src/rtl/zbuffer.sv" && fail "the depth test's line was not found"
status=0
"$exe" cosim --dut bug/testbench/dut/rastersim_dut.f --top rastersim_dut "${flags[@]}" --compare frame > bug.txt 2> bug.err || status=$?
[ "$status" -eq 1 ] || fail "the <= depth test: exit $status, not 1"
line="$(grep -m1 '^frame ' bug.txt)" || fail "no failing frame reported"
case "$line" in *"colour word"* | *"depth word"*) ;; *) fail "the report names no buffer word: $line" ;; esac
replay="${line##*; replay: }"
replay="${replay%%; waveform: *}"
case "$replay" in "rastersim cosim --dut "*" --frame "*) ;; *) fail "no replay command: $line" ;; esac
wave="${line##*; waveform: }"
[ -s "$wave" ] || fail "no waveform at $wave"
status=0
eval "\"$exe\" ${replay#rastersim }" > replay.txt 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "the replay command exited $status, not 1: $replay"
grep -q "^0 passed, 1 failed$" replay.txt || fail "the replay did not fail its one frame: $(tail -1 replay.txt)"

# The installed template as it stands: a design that never takes a triangle.
mkdir stuck
cp "$src/testbench/dut/rastersim_dut_template.sv" stuck/
status=0
"$exe" cosim --dut stuck --top rastersim_dut_template "${flags[@]}" --count 0 --frame 0 > stuck.txt 2>&1 || status=$?
[ "$status" -eq 1 ] || fail "a stalled design: exit $status, not 1"
grep -q "the design stalled: cmd_ready stayed low for [0-9]* cycles with triangle 0 offered" stuck.txt ||
  fail "the stall is not named: $(grep -m1 '^frame' stuck.txt)"

# Bad input.
printf 'rastersim_dut.sv\n+define+X\n' > bad.f
cp "$src/testbench/dut/rastersim_dut.sv" .
status=0
"$exe" cosim --dut bad.f --top rastersim_dut "${flags[@]}" > bad.txt 2>&1 || status=$?
[ "$status" -eq 2 ] || fail "an unknown file-list option: exit $status, not 2"
grep -q "bad.f:2: '+define+X' is not a source file" bad.txt || fail "bad.f:2 not named: $(cat bad.txt)"
status=0
"$exe" cosim --dut missing.f --top x "${flags[@]}" > missing.txt 2>&1 || status=$?
[ "$status" -eq 2 ] || fail "a missing file list: exit $status, not 2"
status=0
"$exe" cosim --dut bad.f "${flags[@]}" > notop.txt 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q "needs --top" notop.txt || fail "--dut without --top: exit $status"

# --wave: the last frame's waveform of the design, a stalled one's up to the stall, a window of
# cycles from the first handshake, FST or VCD, each with its GTKWave save file.
status=0
"$exe" cosim --dut stuck --top rastersim_dut_template --wave w.fst "${flags[@]}" --count 0 --frame 0 > wave.txt 2>&1 || status=$?
[ "$status" -eq 1 ] && [ -s w.fst ] && grep -q 'dumpfile.*/w.fst"' w.fst.gtkw || fail "--wave of a stalled design: exit $status: $(cat wave.txt)"
"$exe" cosim "${memory[@]}" "${flags[@]}" --count 1 --wave w.vcd --wave-from 10 --wave-to 20 > vcd.txt 2>&1 ||
  fail "--wave w.vcd with --dut: $(tail -3 vcd.txt)"
grep -q '^\$enddefinitions' w.vcd && grep -q 'mem_rd_valid' w.vcd && grep -q 'dumpfile.*/w.vcd"' w.vcd.gtkw ||
  fail "no VCD of the design with its save file"
# 11 cycles: 22 half-cycle times in the window.
[ "$(grep -c '^#' w.vcd)" -le 23 ] || fail "the window 10..20 holds $(grep -c '^#' w.vcd) times"
status=0
"$exe" cosim --unit zbuffer --dut stuck --top rastersim_dut_template --wave u.fst "${flags[@]}" > unitwave.txt 2>&1 || status=$?
[ "$status" -eq 2 ] && grep -q -- "--replay-dir" unitwave.txt || fail "--unit with --wave: exit $status: $(cat unitwave.txt)"
[ ! -e u.fst ] || fail "--wave with --unit wrote u.fst"
echo "dut_path_test: rastersim's core passes cycle, stream, triangle and frame, with and without the memory port; the latency, the <= depth test, the stall and bad input are caught"
