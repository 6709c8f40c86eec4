#!/usr/bin/env bash
# Builds the libFuzzer targets of tests/fuzz with clang (-fsanitize=fuzzer,address,undefined, every
# finding fatal) and runs each one from its checked-in seed corpus (tests/fuzz/corpus/<target>/).
#
# Usage: scripts/fuzz.sh [--time SECONDS | --runs N] [--build-dir DIR] [--no-build] [TARGET ...]
#   --time SECONDS  run each target for this long (default 60)
#   --runs N        instead, run each target for N inputs from seed 1 (deterministic: the ctest smoke)
#   --build-dir DIR default build-fuzz; configured with CXX=clang++ -DRASTERSIM_FUZZ=ON
#   --no-build      use the binaries already in DIR/tests/fuzz
#   TARGET          tri obj scene profile setup (default: all five)
# Inputs that reach new code are kept in DIR/fuzz-corpus/<target>/ (the checked-in corpus is only
# read). A finding (crash, sanitizer report, broken invariant, timeout over 10 s, memory over 2 GB)
# is saved as DIR/fuzz-findings/<target>-<kind>-<hash> and the script exits 1 after printing the
# command that replays it. Per target it prints: inputs executed, seconds, corpus size, result.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
time_per_target=60
runs=""
build="$root/build-fuzz"
do_build=1
targets=()
while [ $# -gt 0 ]; do
  case "$1" in
    --time) time_per_target="$2"; shift 2 ;;
    --runs) runs="$2"; shift 2 ;;
    --build-dir) build="$2"; shift 2 ;;
    --no-build) do_build=0; shift ;;
    -h|--help) sed -n '2,16p' "$0" | sed 's/^# \{0,1\}//'; exit 0 ;;
    -*) echo "fuzz.sh: unknown option $1" >&2; exit 2 ;;
    *) targets+=("$1"); shift ;;
  esac
done
[ ${#targets[@]} -eq 0 ] && targets=(tri obj scene profile setup)
for t in "${targets[@]}"; do
  [ -d "$root/tests/fuzz/corpus/$t" ] || { echo "fuzz.sh: unknown target '$t' (tri obj scene profile setup)" >&2; exit 2; }
done

if [ $do_build -eq 1 ]; then
  command -v clang++ > /dev/null || { echo "fuzz.sh: clang++ not found (apt-get install clang; libFuzzer comes with it)" >&2; exit 2; }
  # Only the fuzz targets are built; the RTL (Verilator) is not needed for them.
  CXX=clang++ CC=clang cmake -S "$root" -B "$build" -DRASTERSIM_FUZZ=ON -DRASTERSIM_TESTS=OFF \
    -DRASTERSIM_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_verilator=ON -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g" > /dev/null
  cmake --build "$build" -j"$(nproc)" --target fuzz_targets
fi

status=0
for t in "${targets[@]}"; do
  binary="$build/tests/fuzz/fuzz_$t"
  [ -x "$binary" ] || { echo "fuzz.sh: $binary is not built" >&2; exit 2; }
  corpus="$build/fuzz-corpus/$t"
  findings="$build/fuzz-findings"
  log="$build/fuzz-logs/$t.log"
  mkdir -p "$corpus" "$findings" "$(dirname "$log")"
  options=(-max_len=4096 -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$findings/$t-")
  [ -f "$root/tests/fuzz/dict/$t.dict" ] && options+=(-dict="$root/tests/fuzz/dict/$t.dict")
  if [ -n "$runs" ]; then options+=(-seed=1 -runs="$runs"); else options+=(-max_total_time="$time_per_target"); fi
  if "$binary" "${options[@]}" "$corpus" "$root/tests/fuzz/corpus/$t" > "$log" 2>&1; then
    result="no finding"
  else
    result="FINDING"
    status=1
  fi
  executed="$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -1)"
  seconds="$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -1)"
  size="$(ls "$corpus" | wc -l)"
  echo "fuzz_$t: ${executed:-?} inputs in ${seconds:-?} s, $size new corpus inputs, $result (log $log)"
  if [ "$result" = FINDING ]; then
    grep -E "ERROR|invariant broken|runtime error|uncaught|deadly|Test unit written" "$log" | head -20
    artifact="$(sed -n 's/.*Test unit written to \(.*\)$/\1/p' "$log" | tail -1)"
    [ -n "$artifact" ] && echo "replay: $binary $artifact"
  fi
done
exit $status
