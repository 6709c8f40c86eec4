#!/usr/bin/env bash
# Profiles the build has no verilated RTL for run anyway (docs/debugging.md "Any profile on the RTL
# backends"): a 48x48 profile, sampling pixel corners by the bottom-left fill rule with truncated
# colours (the core's PIXEL_CENTER, FILL_RULE and COLOR_ROUNDING), through --backend rtl, cosim and
# systemc, and a textured 48x32 one
# through systemc, verilated on demand into a cache of this test's own. Checks that two runs started together build the module once and agree;
# the outputs equal the model's; a later run loads the module without building (and prints how long
# it took); a bad cache folder, an invalid profile or a stall pattern (no RTL build runs one) is an
# error (exit 2) that writes and builds nothing.
# Usage: check-modules-on-demand.sh BUILD_DIR
set -euo pipefail
exe="$(cd "$1" && pwd)/rastersim"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
cd "$work"
export RASTERSIM_CACHE_DIR="$work/cache"
fail() { echo "check-modules-on-demand: $*"; exit 1; }
conventions=(--pixel-center corner --fill-rule bottom_left --color-rounding truncate)
profile=(--width 48 --height 48 --scene default "${conventions[@]}")

"$exe" render --backend model "${profile[@]}" -o model.png --fragments model.csv > /dev/null
"$exe" render --backend model --width 48 --height 48 --scene default -o default.png --fragments default.csv > /dev/null
cmp -s default.csv model.csv && fail "the conventions change no fragment of this scene: the test would not see them"

# Two runs at once: one builds, the other waits for it; both get the same module.
"$exe" render --backend rtl "${profile[@]}" -o a.png --fragments a.csv > a.out 2> a.err & first=$!
"$exe" render --backend rtl "${profile[@]}" -o b.png --fragments b.csv > b.out 2> b.err & second=$!
wait $first || fail "the first concurrent run failed: $(cat a.err)"
wait $second || fail "the second concurrent run failed: $(cat b.err)"
cat a.err
builds=$(cat a.err b.err | grep -c '^rastersim: verilating (') || true
[ "$builds" -eq 1 ] || fail "two runs at once verilated $builds times, not once"
grep -q '^rastersim: compiling \[' a.err b.err || fail "no build progress was shown"
for out in a b; do
  cmp -s $out.png model.png || fail "render --backend rtl ($out) differs from the model's image"
  cmp -s $out.csv model.csv || fail "render --backend rtl ($out) differs from the model's fragments"
done
modules=("$RASTERSIM_CACHE_DIR"/modules/rtl-48-48-*/librastersim_module.so)
[ ${#modules[@]} -eq 1 ] && [ -f "${modules[0]}" ] || fail "expected one RTL module in the cache: ${modules[*]}"
if ls -d "$RASTERSIM_CACHE_DIR"/modules/*.staging-* 2> /dev/null; then fail "a staging folder was left behind"; fi

# A later run loads the module: no build, the library untouched.
stamp=$(stat -c %Y.%s "${modules[0]}")
start=$(date +%s%N)
"$exe" render --backend rtl "${profile[@]}" -o c.png > /dev/null 2> c.err
echo "second run of render --backend rtl ${profile[*]}: $(( ($(date +%s%N) - start) / 1000000 )) ms"
[ ! -s c.err ] || fail "the second run printed: $(cat c.err)"
[ "$(stat -c %Y.%s "${modules[0]}")" = "$stamp" ] || fail "the second run rebuilt the module"
cmp -s c.png model.png || fail "the second run's image differs from the model's"

# cosim takes the same module; random frames vary the runtime settings around it.
"$exe" cosim --width 48 --height 48 "${conventions[@]}" --count 20 > cosim.out 2> cosim.err || fail "cosim failed: $(tail -3 cosim.out)"
grep -Eq '^[0-9]+ passed, 0 failed' cosim.out || fail "cosim did not pass: $(tail -1 cosim.out)"
[ ! -s cosim.err ] || fail "cosim rebuilt the module: $(cat cosim.err)"

# The SystemC backend builds its own module for the profile.
if "$exe" render --help | grep -q 'systemc (the verilated core'; then
  "$exe" render --backend systemc "${profile[@]}" -o sc.png --fragments sc.csv > /dev/null 2> sc.err ||
    fail "render --backend systemc failed: $(cat sc.err)"
  grep -q '^rastersim: verilating (' sc.err || fail "the SystemC module was not built: $(cat sc.err)"
  cmp -s sc.png model.png && cmp -s sc.csv model.csv || fail "render --backend systemc differs from the model"
  start=$(date +%s%N)
  "$exe" render --backend systemc "${profile[@]}" -o sc2.png > /dev/null 2> sc2.err
  echo "second run of render --backend systemc ${profile[*]}: $(( ($(date +%s%N) - start) / 1000000 )) ms"
  [ ! -s sc2.err ] || fail "the second SystemC run printed: $(cat sc2.err)"

  # The texture unit in the SystemC system: a core built with it, the texture memory model with its
  # latency and stall pattern; the textured floor scene equals the model's in every fragment and
  # cycle and in every counter (serial setup: the smallest textured core to build).
  textured=(--scene floor --width 48 --height 32 --setup-interval 0 --texture-unit true --texture-latency 3
            --texture-stall-percent 30 --texture-stall-seed 2)
  "$exe" render --backend model "${textured[@]}" -o tm.png --fragments tm.csv --stats tm.json > /dev/null
  "$exe" render --backend systemc "${textured[@]}" -o ts.png --fragments ts.csv --stats ts.json > /dev/null 2> ts.err ||
    fail "render --backend systemc with the texture unit failed: $(cat ts.err)"
  grep -q 'TEXTURE=1 .*is not built in' ts.err || fail "no textured SystemC module was built: $(cat ts.err)"
  cmp -s tm.png ts.png && cmp -s tm.csv ts.csv && cmp -s tm.json ts.json ||
    fail "render --backend systemc with the texture unit differs from the model"
  python3 -c 'import json, sys; u = json.load(open("ts.json"))["units"]["texture"]; sys.exit(u["busy"] == 0 or u["stall"] == 0)' ||
    fail "the texture unit was never busy or its memory never stalled"
fi

# Errors: a cache folder that cannot be made, and an invalid profile (refused before any build).
touch not-a-folder
status=0
RASTERSIM_CACHE_DIR="$work/not-a-folder" "$exe" render --backend rtl --width 40 --height 40 --scene default \
  -o bad.png > /dev/null 2> bad.err || status=$?
[ $status -eq 2 ] || fail "a cache path that is a file: exit $status, not 2"
grep -q 'cannot create the module cache' bad.err || fail "no clear error for the bad cache: $(cat bad.err)"
[ ! -e bad.png ] || fail "an image was written although the run failed"
status=0
RASTERSIM_CACHE_DIR="$work/unused" "$exe" render --backend rtl --width 40 --height 0 --scene default \
  > /dev/null 2> invalid.err || status=$?
[ $status -eq 2 ] || fail "an invalid profile: exit $status, not 2"
[ ! -e "$work/unused" ] || fail "an invalid profile started a build"
status=0
RASTERSIM_CACHE_DIR="$work/unused" "$exe" render --backend rtl --width 40 --height 40 --memory-stall-percent 20 \
  --scene default > /dev/null 2> stall.err || status=$?
[ $status -eq 2 ] || fail "a stall pattern on the RTL backend: exit $status, not 2"
grep -q 'memory_stall_percent 20' stall.err || fail "the stall refusal does not name it: $(cat stall.err)"
[ ! -e "$work/unused" ] || fail "a profile no build can run (a stall pattern) started a build"
echo "check-modules-on-demand: passed"
