#!/usr/bin/env bash
# Installs a build into a temporary prefix, builds examples/scoreboard against the installed tree
# (the C example twice: CMake find_package with the static library, pkg-config with the shared
# one; the C++ example with find_package), the Python
# example examples/python/scoreboard.py with the installed module, examples/dpi/render_tb.sv (the
# model alone through DPI-C), and the DPI
# example examples/dpi (the installed RTL under Verilator, the model as its scoreboard through
# DPI-C; and again with an injected RTL bug, which it must report), runs them and
# the installed `rastersim render` on the same triangles, and requires the same fragments (every
# field and cycle), the same frame cycles, and final buffers equal to those replayed from the
# CLI's fragment trace; on docs/examples/worked.tri and on the default scene (or on the given
# profile and triangles). The installed module's pytest runs against the installed module, and
# `render --backend rtl` at a profile no build holds (40 x 30) is verilated from the installed
# sources. Everything after the install runs with the checkout and the build folder hidden (an
# empty tmpfs over each, in a private mount namespace: unshare -m), as after moving them away.
# Usage: check-install.sh BUILD_DIR [PROFILE.json TRIANGLES.tri]
set -euo pipefail
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
if [ -z "${RASTERSIM_INSTALLED_PREFIX:-}" ]; then
  root="$(cd "$(dirname "$0")/.." && pwd)"
  build="$(cd "${1:?usage: check-install.sh BUILD_DIR [PROFILE.json TRIANGLES.tri]}" && pwd)"
  prefix="$work/prefix"
  cmake --install "$build" --prefix "$prefix" > "$work/install.log"
  # The rest runs on the installed tree alone, as after moving the checkout away: in a private mount
  # namespace with an empty tmpfs over the build folder and the checkout.
  unshare -m --propagation private true 2> /dev/null ||
    { echo "check-install: cannot hide the checkout (unshare -m needs root or user namespaces)"; exit 1; }
  cp "$0" "$work/check-install.sh"
  given=()
  if [ $# -ge 3 ]; then
    cp "$2" "$work/given.json" && cp "$3" "$work/given.tri"
    given=("$work/given.json" "$work/given.tri")
  fi
  status=0
  cd "$work"  # a working folder that stays in sight (programs that look up their folder fail otherwise)
  # shellcheck disable=SC2016  # expanded by the inner shell
  unshare -m --propagation private bash -c 'mount -t tmpfs none "$1" && mount -t tmpfs none "$2" && shift 2 && exec "$@"' \
    _ "$build" "$root" env RASTERSIM_INSTALLED_PREFIX="$prefix" RASTERSIM_HIDDEN_CHECKOUT="$root" bash "$work/check-install.sh" hidden "${given[@]}" ||
    status=$?
  exit $status
fi
prefix="$RASTERSIM_INSTALLED_PREFIX"
if [ -e "$RASTERSIM_HIDDEN_CHECKOUT/CMakeLists.txt" ]; then echo "check-install: the checkout is still in sight"; exit 1; fi
for f in bin/rastersim include/rastersim/rastersim.h include/rastersim/model/pipeline.h \
         lib/cmake/rastersim/rastersimConfig.cmake lib/pkgconfig/rastersim.pc share/rastersim/rtl/rastersim_top.sv \
         share/doc/rastersim/library.md; do
  [ -e "$prefix/$f" ] || { echo "check-install: $f is not installed"; exit 1; }
done
# The Python module where Debian's python3 looks for a /usr/local prefix.
python_dir="lib/python$(/usr/bin/python3 -c 'import sys; print("%d.%d" % sys.version_info[:2])')/dist-packages"
ls "$prefix"/lib/librastersim_model.a "$prefix"/lib/librastersim_model.so "$prefix/$python_dir"/rastersim*.so > /dev/null
/usr/bin/python3 -c "import sys; sys.exit('/usr/local/$python_dir' not in sys.path)" \
  || { echo "check-install: /usr/local/$python_dir is not on python3's sys.path"; exit 1; }
# The module's own tests, installed, against the installed module, CLI and docs, outside the checkout.
(cd "$work" && PYTHONPATH="$prefix/$python_dir" RASTERSIM_CLI="$prefix/bin/rastersim" \
  RASTERSIM_DOCS_DIR="$prefix/share/doc/rastersim" /usr/bin/python3 -m pytest -q -p no:cacheprovider \
  --basetemp="$work/pytest" "$prefix/share/rastersim/python-tests" > "$work/pytest.log" 2>&1) \
  || { cat "$work/pytest.log"; echo "check-install: the installed module's tests failed"; exit 1; }
(cd "$work" && PYTHONPATH="$prefix/$python_dir" /usr/bin/python3 -c \
  "import rastersim, sys; sys.exit(not rastersim.__file__.startswith('$prefix/'))") \
  || { echo "check-install: python3 does not import the installed module"; exit 1; }

# The example as a user builds it: find_package (static library).
cmake -S "$prefix/share/doc/rastersim/examples/scoreboard" -B "$work/sb" -DCMAKE_PREFIX_PATH="$prefix" \
  -DCMAKE_BUILD_TYPE=Release > "$work/configure.log"
cmake --build "$work/sb" > "$work/build.log"
# A C-only CMake project (no C++ compiler enabled) linking the static library by its usual name,
# rastersim::rastersim: the C++ runtime comes with it.
mkdir -p "$work/c-only-src"
cp "$prefix/share/doc/rastersim/examples/scoreboard/scoreboard.c" "$work/c-only-src/"
cat > "$work/c-only-src/CMakeLists.txt" <<'CMAKE'
cmake_minimum_required(VERSION 3.20)
project(c_only LANGUAGES C)
find_package(rastersim 0.1 REQUIRED)
add_executable(scoreboard scoreboard.c)
target_link_libraries(scoreboard PRIVATE rastersim::rastersim)
CMAKE
cmake -S "$work/c-only-src" -B "$work/c-only" -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_BUILD_TYPE=Release \
  > "$work/c-only.configure.log"
cmake --build "$work/c-only" > "$work/c-only.build.log" 2>&1 \
  || { echo "check-install: a C-only CMake project does not link rastersim::model"; tail -5 "$work/c-only.build.log"; exit 1; }
# The C++ headers from the one include folder, as <rastersim/...>; the generic model/ and fast/
# names are not on the include path.
cat > "$work/headers.cpp" <<'CPP'
#include <rastersim/fast/fast_walk.h>
#include <rastersim/model/pipeline.h>
int main() { return rastersim::Profile{}.width > 0 ? 0 : 1; }
CPP
printf '#include <model/pipeline.h>\n' > "$work/generic.cpp"
# shellcheck disable=SC2046
c++ -std=c++17 -fsyntax-only $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags rastersim) "$work/headers.cpp" \
  || { echo "check-install: <rastersim/model/pipeline.h> does not compile from the installed include folder"; exit 1; }
# shellcheck disable=SC2046
if c++ -std=c++17 -fsyntax-only $(PKG_CONFIG_PATH="$prefix/lib/pkgconfig" pkg-config --cflags rastersim) "$work/generic.cpp" 2> /dev/null; then
  echo "check-install: the installed include path exposes <model/pipeline.h>"; exit 1
fi
# And with pkg-config (shared library).
export PKG_CONFIG_PATH="$prefix/lib/pkgconfig"
# shellcheck disable=SC2046
cc -std=c99 -Wall -Werror -o "$work/scoreboard_shared" "$prefix/share/doc/rastersim/examples/scoreboard/scoreboard.c" \
  $(pkg-config --cflags --libs rastersim)

compare() {  # PROFILE TRIANGLES
local profile="$1" triangles="$2"
"$prefix/bin/rastersim" render "$triangles" --profile "$profile" --fragments "$work/cli.csv" \
  --stats "$work/cli.json" > /dev/null
"$work/sb/scoreboard" "$profile" "$triangles" "$work/static.csv" "$work/static.txt" > "$work/static.out"
LD_LIBRARY_PATH="$prefix/lib" "$work/scoreboard_shared" "$profile" "$triangles" "$work/shared.csv" \
  "$work/shared.txt" > "$work/shared.out"
PYTHONPATH="$prefix/$python_dir" /usr/bin/python3 \
  "$prefix/share/doc/rastersim/examples/python/scoreboard.py" "$profile" "$triangles" "$work/python.csv" \
  "$work/python.txt" > "$work/python.out"
"$work/sb/scoreboard_cpp" "$profile" "$triangles" "$work/cpp.csv" "$work/cpp.txt" > "$work/cpp.out"
"$work/c-only/scoreboard" "$profile" "$triangles" "$work/c-only.csv" "$work/c-only.txt" > "$work/c-only.out"
"$work/dpi/render_tb" +tri="$triangles" +profile="$profile" +fragments="$work/dpi-render.csv" \
  +buffers="$work/dpi-render.txt" > "$work/dpi-render.out"
readelf -d "$work/scoreboard_shared" | grep -q 'NEEDED.*librastersim_model\.so' \
  || { echo "check-install: the pkg-config build does not use the installed shared library"; exit 1; }

python3 - "$work" <<'PY'
import csv, json, sys
work = sys.argv[1]
cli = list(csv.reader(open(f"{work}/cli.csv")))
stats = json.load(open(f"{work}/cli.json"))
if len(cli) < 2:
    sys.exit("check-install: the CLI wrote no fragments (nothing to compare)")
# The final buffers replayed from the CLI's trace: clear value, then every passing fragment.
profile = stats["profile"]
width, height = profile["width"], profile["height"]
depth = [profile["depth_clear"]] * (width * height)
colour = [0] * (width * height)
for tri, x, y, z, passed, r, g, b, cycle in (map(int, row) for row in cli[1:]):
    if passed:
        if profile["depth_write"]:
            depth[y * width + x] = z
        colour[y * width + x] = (r << 16) | (g << 8) | b
expected_buffers = [f"{d} {c:06x}" for d, c in zip(depth, colour)]
for kind in ("static", "shared", "c-only", "cpp", "python", "dpi-render"):
    rows = list(csv.reader(open(f"{work}/{kind}.csv")))
    if rows != cli:
        diff = next(i for i in range(min(len(rows), len(cli)) + 1) if i >= len(rows) or i >= len(cli) or rows[i] != cli[i])
        sys.exit(f"check-install: {kind} fragments differ from the CLI's at row {diff}: "
                 f"{rows[diff] if diff < len(rows) else 'none'} against {cli[diff] if diff < len(cli) else 'none'}")
    cycles = [l for l in open(f"{work}/{kind}.out") if l.startswith("cycles ")]
    if cycles != [f"cycles {stats['cycles']}\n"]:
        sys.exit(f"check-install: {kind} frame cycles {cycles} against the CLI's {stats['cycles']}")
    buffers = open(f"{work}/{kind}.txt").read().split("\n")[:-1]
    if buffers != expected_buffers:
        bad = next(i for i in range(len(expected_buffers)) if i >= len(buffers) or buffers[i] != expected_buffers[i])
        sys.exit(f"check-install: {kind} buffer word of pixel ({bad % width}, {bad // width}) is "
                 f"{buffers[bad] if bad < len(buffers) else 'missing'}, the replayed trace gives {expected_buffers[bad]}")
print(f"check-install: {len(cli) - 1} fragments, {stats['cycles']} cycles and {width * height} buffer words agree "
      "(CLI, C example static, shared and C-only CMake, C++ example, Python, DPI-C render_tb)")
PY
}

# The DPI example: the installed RTL under Verilator with the installed model as its scoreboard
# through DPI-C; it must agree, and it must catch a bug injected into a copy of the RTL (a flipped
# carry-in of the plane registers' x step) with a message naming triangle, pixel and field.
dpi_example() {  # NAME RTL_DIR
  cmake -S "$prefix/share/doc/rastersim/examples/dpi" -B "$work/$1" -DCMAKE_PREFIX_PATH="$prefix" \
    -DCMAKE_BUILD_TYPE=Release -DRTL_DIR="$2" > "$work/$1.configure.log" 2>&1 \
    || { cat "$work/$1.configure.log"; exit 1; }
  cmake --build "$work/$1" -j"$(nproc)" > "$work/$1.build.log" 2>&1 || { tail -30 "$work/$1.build.log"; exit 1; }
}
dpi_example dpi "$prefix/share/rastersim/rtl"
"$work/dpi/scoreboard_tb" | tee "$work/dpi.out"
grep -q "agree with the model" "$work/dpi.out" || { echo "check-install: the DPI example did not agree"; exit 1; }
cp -r "$prefix/share/rastersim/rtl" "$work/rtl-bug"
python3 - "$work/rtl-bug/plane_register.sv" <<'PY'
import sys
path = sys.argv[1]
text = open(path).read()
old = ": step_x ? value_q + step_x_q"
if text.count(old) != 1:
    sys.exit(f"check-install: mutation anchor found {text.count(old)} times in {path}")
open(path, "w").write(text.replace(old, ": step_x ? value_q + step_x_q + 1'b1"))
PY
dpi_example dpi-bug "$work/rtl-bug"
if "$work/dpi-bug/scoreboard_tb" > "$work/dpi-bug.out"; then
  echo "check-install: the DPI example passed an RTL with an injected bug"; exit 1
fi
grep -m1 "MISMATCH triangle [0-9]*, pixel ([0-9]*, [0-9]*), [a-z]" "$work/dpi-bug.out" \
  || { echo "check-install: the DPI example failed without naming triangle, pixel and field"; cat "$work/dpi-bug.out"; exit 1; }
echo "check-install: the DPI example caught the injected bug"
# docs/library.md shows these runs: its lines must be what they print.
for line in "$(grep -m1 'agree with the model' "$work/dpi.out")" "$(grep -m1 'MISMATCH' "$work/dpi-bug.out")" \
            "$(grep -m1 'FAILED, ' "$work/dpi-bug.out")"; do
  grep -qxF -- "$line" "$prefix/share/doc/rastersim/library.md" || { echo "check-install: docs/library.md does not show '$line'"; exit 1; }
done

if [ $# -ge 3 ]; then
  compare "$(realpath "$2")" "$(realpath "$3")"
else
  compare "$prefix/share/doc/rastersim/examples/worked.json" "$prefix/share/doc/rastersim/examples/worked.tri"
  echo '{}' > "$work/default.json"
  "$prefix/bin/rastersim" render --scene default --dump-tri "$work/default.tri" > /dev/null
  compare "$work/default.json" "$work/default.tri"
fi

# The RTL backend at a profile no build holds: verilated on demand from the installed sources
# (share/rastersim/source) into an empty module cache, and equal to the model.
for backend in model rtl; do
  RASTERSIM_CACHE_DIR="$work/cache" "$prefix/bin/rastersim" render --scene default --width 40 --height 30 \
    --backend "$backend" --stats "$work/$backend-40x30.json" > "$work/$backend-40x30.out" 2>&1 ||
    { cat "$work/$backend-40x30.out"; echo "check-install: render --backend $backend at 40x30 failed"; exit 1; }
done
python3 - "$work/model-40x30.json" "$work/rtl-40x30.json" <<'PY'
import json, sys
model, rtl = (json.load(open(p)) for p in sys.argv[1:])
for key in ("fragments", "cycles", "depth_pass"):
    if model.get(key) != rtl.get(key):
        sys.exit(f"check-install: render --backend rtl at 40x30: {key} {rtl.get(key)}, the model's {model.get(key)}")
PY
echo "check-install: render --backend rtl at 40x30 (verilated from the installed sources) equals the model"
