#!/usr/bin/env bash
# Hostile inputs under a 4 GiB address-space limit (docs/robustness.md, tests/hostile/README.md):
# every file of tests/hostile/, every other input file in tests/ and docs/examples/, and a few
# generated large ones, as the input of `rastersim render`
# and (JSON files) as its --profile, must render (exit 0) or be refused (exit 2) with a message
# naming the file, never end in bad_alloc, a crash, a signal or a hang (60 s), and write nothing
# but the --stats output. Then hostile counts, names and numbers on the command line of every
# command, under the same rule, the message naming the option or input. Prints one line per run and
# a summary; exit 1 on any violation.
# Usage: hostile-corpus.sh BUILD_DIR
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="$(cd "${1:?usage: hostile-corpus.sh BUILD_DIR}" && pwd)"
rastersim="$build/rastersim"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
corpus="$work/corpus"
mkdir -p "$corpus"
cp "$root"/tests/hostile/*.tri "$root"/tests/hostile/*.obj "$root"/tests/hostile/*.json "$corpus/"
# And every other input file kept in the repository (the fuzzers' seeds, the docs' examples).
for f in $(cd "$root" && find tests/fuzz/corpus docs/examples -name '*.tri' -o -name '*.obj' -o -name '*.json'); do
  cp "$root/$f" "$corpus/$(echo "$f" | tr '/' '_')"
done

# The large members, made here rather than kept in the repository.
ln -s /dev/zero "$corpus/endless.tri"
ln -s /dev/zero "$corpus/endless.obj"
ln -s /dev/zero "$corpus/endless.json"
mkfifo "$corpus/fifo.tri" "$corpus/fifo.json"  # no writer: a reader that opens one blocks for ever
python3 - "$corpus" <<'PY'
import json, random, sys
corpus = sys.argv[1]
rng = random.Random(20261125)
open(f"{corpus}/million-tokens.tri", "w").write("1 " * 2_000_000 + "\n")
open(f"{corpus}/nested-200000.json", "w").write("[" * 200_000 + "]" * 200_000 + "\n")
for ext in ("tri", "obj", "json"):
    open(f"{corpus}/random-bytes.{ext}", "wb").write(bytes(rng.getrandbits(8) for _ in range(200_000)))
sphere = {"surface": "sphere", "params": {"segments": 1024, "rings": 1024}}
json.dump({"objects": [sphere] * 20}, open(f"{corpus}/twenty-spheres.json", "w"))
# 600,000 lights, each lighting every vertex (this ran for hours).
small = {"surface": "sphere", "params": {"segments": 8, "rings": 8}}
json.dump({"objects": [small], "lights": [{"direction": [0, 0, 1]}] * 600_000}, open(f"{corpus}/many-lights.json", "w"))
# 255-corner faces: under the size cap, past the triangle limit once fanned.
face = "f" + "".join(f" {1 + k % 4}" for k in range(255)) + "\n"
open(f"{corpus}/many-corners.obj", "w").write("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n" + face * 16_000)
with open(f"{corpus}/many-triangles.tri", "w") as f:
    for i in range(200_000):
        x, y = rng.uniform(0, 60), rng.uniform(0, 44)
        f.write(f"{x} {y} 0.5 {x + 3} {y} 0.5 {x} {y + 3} 0.5\n")
PY

runs=0
bad=0
# check NAME ARGS...: one render in a fresh folder, with --stats stats.json.
check() { run_in_fresh_folder --stats "$@"; }  # the message: "rastersim: ... NAME ..."
# check_command NAME ARGS...: one run of any command, nothing but its stdout and stderr written.
check_command() { run_in_fresh_folder --no-stats "$@"; }
run_in_fresh_folder() {
  local stats="$1" name="$2"; shift 2
  local prefix=""
  if [ "$stats" = --stats ]; then set -- "$@" --stats stats.json; prefix="^rastersim: "; fi
  local dir="$work/run"
  rm -rf "$dir"; mkdir -p "$dir"
  local code=0
  (cd "$dir" && timeout 60 prlimit --as=4294967296 "$rastersim" "$@" > out.txt 2> err.txt) || code=$?
  runs=$((runs + 1))
  local message
  message="$(head -c 160 "$dir/err.txt" | head -1)"
  local problem=""
  if [ "$code" -eq 124 ]; then problem="a hang (killed after 60 s)"
  elif [ "$code" -ne 0 ] && [ "$code" -ne 2 ]; then problem="exit $code"
  elif grep -q "bad_alloc\|std::\|terminate called\|Sanitizer" "$dir/err.txt"; then problem="an internal error"
  elif [ "$code" -eq 2 ] && ! grep -F -- "$name" "$dir/err.txt" | grep -q "$prefix"; then problem="a message not naming $name"
  fi
  local extra
  extra="$(cd "$dir" && ls -A | grep -v '^out.txt$\|^err.txt$\|^stats.json$' || true)"
  [ -n "$extra" ] && problem="${problem:+$problem, }wrote $extra"
  [ "$code" -eq 2 ] && [ -e "$dir/stats.json" ] && problem="${problem:+$problem, }a partial stats.json"
  if [ -n "$problem" ]; then
    bad=$((bad + 1))
    echo "FAIL $* -> $problem: $message"
  else
    echo "ok   exit $code  $*  ${message:0:110}"
  fi
}

for f in "$corpus"/*; do
  name="$(basename "$f")"
  check "$name" render "$f" --width 64 --height 48
  case "$name" in
    *.json) check "$name" render --scene fan --width 64 --height 48 --profile "$f" ;;
  esac
done
# A texture that never ends.
mkdir -p "$work/textures"
ln -s /dev/zero "$work/textures/endless.png"
check endless.png render --scene fan --width 64 --height 48 --texture-unit true --texture "$work/textures/endless.png"
# The command line: counts past their limits, empty names, numbers out of range, bytes in names.
many="$(seq -s, 1 101)"
check_command --triangles bench --triangles 10000000
check_command --vary sweep --vary "width=$many" --vary "height=$many" --out "$work/run/sweep"
check_command input render ""
check_command --scene render --scene ""
check_command input vectors "" --out "$work/run/package"
check_command --seed render --scene fan --seed -1
check_command --seed render --scene fan --seed 18446744073709551616
check_command --width render --scene fan --width 2147483648
check_command --eye render --width 64 --height 48 --eye 1e300,0,0
# Raw bytes in a name are shown as \xNN (the file does not exist).
check_command 'bytes-\xff\xe9.tri' render $'bytes-\xff\xe9.tri' --width 64 --height 48
echo "hostile-corpus: $runs runs, $bad violations"
[ "$bad" -eq 0 ]
