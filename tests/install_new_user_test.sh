#!/usr/bin/env bash
# docs/verification.md "From an installed rastersim": a new user's design, in a folder outside the
# source tree, verified with the installed program and the installed interface file only, by the
# commands the docs show. The design is the installed example's rasterizer renamed into the user's
# module (the "edit" step); the template as installed is a valid design that stalls, reported as
# such. The module must be built from the installed copy of the sources, not the source tree.
# Usage: install_new_user_test.sh BUILD_DIR
set -euo pipefail
build="$(cd "${1:?usage: install_new_user_test.sh BUILD_DIR}" && pwd)"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
export RASTERSIM_CACHE_DIR="$work/cache"
fail() { echo "install_new_user_test: $*" >&2; exit 1; }
prefix="$work/rastersim"

# The docs' commands, with $HOME/rastersim as $prefix.
cmake --install "$build" --prefix "$prefix" > "$work/install.log"
mkdir "$work/my_design" && cd "$work/my_design"
cp "$prefix/share/rastersim/verification/rastersim_dut_template.sv" my_rasterizer.sv
# The edit: the template's module, stalled as installed, must be recognised as such first.
status=0
"$prefix/bin/rastersim" cosim --dut . --top rastersim_dut_template --width 64 --height 48 --count 0 --frame 0 \
  > stalled.txt 2>&1 || status=$?
[ "$status" -eq 1 ] && grep -q "the design stalled: cmd_ready stayed low" stalled.txt ||
  fail "the installed template is not reported as a stalled design (exit $status): $(tail -3 stalled.txt)"
# ... then a rasterizer inside its ports: the installed example's, as the user's module.
sed 's/^module bbox_rasterizer #(/module my_rasterizer #(/' \
  "$prefix/share/doc/rastersim/examples/bbox_rasterizer/bbox_rasterizer.sv" > my_rasterizer.sv
grep -q '^module my_rasterizer #(' my_rasterizer.sv || fail "the example's module line was not found"
"$prefix/bin/rastersim" cosim --dut . --top my_rasterizer --width 64 --height 48 --compare triangle > first.txt 2>&1 ||
  fail "the user's design failed: $(grep -m1 '^frame' first.txt || tail -3 first.txt)"
"$prefix/bin/rastersim" cosim --dut . --top my_rasterizer --width 64 --height 48 --compare triangle --count 300 \
  --jobs 2 --junit results.xml > run.txt 2>&1 || fail "the longer run failed: $(grep -m1 '^frame' run.txt || tail -3 run.txt)"
grep -q "^[0-9]* passed, 0 failed$" run.txt || fail "no passed line: $(tail -1 run.txt)"
grep -q '<testsuite name="rastersim.cosim' results.xml || fail "no JUnit report"

# Built from the installed sources: each module's build log (its cmake -S line) names the installed
# copy, none the source tree.
source_tree="$(cd "$(dirname "$0")/.." && pwd)"
grep -rl --include=build.log -- "-S $source_tree/" "$RASTERSIM_CACHE_DIR" && fail "a module was built from $source_tree"
grep -rlq --include=build.log -- "-S $prefix/share/rastersim/source/testbench/dut" "$RASTERSIM_CACHE_DIR" ||
  fail "no design was built from $prefix/share/rastersim/source"
echo "install_new_user_test: a design outside the source tree passes through the installed rastersim: $(tail -1 run.txt)"
