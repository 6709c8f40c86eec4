#!/usr/bin/env bash
# The threaded render (fast/threaded_render.h) and sweep's banded depth-error meter under
# ThreadSanitizer: the model, the unit suite and the CLI's tests built with -fsanitize=thread in
# their own build folder, then tests/test_threads.cpp's tests and the meter's run; any report fails
# (halt_on_error). ctest label tsan (and long: the build takes minutes).
# Usage: scripts/test-tsan.sh [BUILD_DIR]   (default build-tsan)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-tsan}"
jobs="${RASTERSIM_TSAN_JOBS:-2}"
cmake -S "$root" -B "$build" -DRASTERSIM_BENCH=OFF -DCMAKE_DISABLE_FIND_PACKAGE_verilator=ON \
  -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g" -DCMAKE_CXX_FLAGS="-fsanitize=thread" \
  -DCMAKE_EXE_LINKER_FLAGS="-fsanitize=thread" -DCMAKE_SHARED_LINKER_FLAGS="-fsanitize=thread" >/dev/null
cmake --build "$build" -j"$jobs" --target rastersim_tests rastersim_cli_tests
export TSAN_OPTIONS="halt_on_error=1:exitcode=66:second_deadlock_stack=1"
# TSan's shadow memory needs the address layout without randomization on kernels whose mmap
# randomization is wider than it expects; setarch -R turns it off for the command only.
run() {
  if command -v setarch >/dev/null && setarch "$(uname -m)" -R true 2>/dev/null; then
    setarch "$(uname -m)" -R "$@"
  else
    "$@"
  fi
}
run "$build/tests/rastersim_tests" --gtest_filter='*Threads*'
run "$build/cli/rastersim_cli_tests" --gtest_filter='DepthErrorMeter.*'
