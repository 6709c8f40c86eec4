#!/usr/bin/env bash
# The whole C++ test suite built with AddressSanitizer + UndefinedBehaviorSanitizer (gcc, every
# finding fatal), in its own build folder. Verilator's RTL backend is left out (it is what costs:
# verilating and compiling the top takes most of a normal build) and so are the tests that run no
# C++ of ours (labels rtl, formal, fuzz), and the long runs. docs/robustness.md.
# Usage: scripts/test-sanitizers.sh [BUILD_DIR]   (default build-sanitize)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$root/build-sanitize}"
cmake -S "$root" -B "$build" -DRASTERSIM_SANITIZE=ON -DRASTERSIM_BENCH=OFF \
  -DCMAKE_DISABLE_FIND_PACKAGE_verilator=ON -DCMAKE_BUILD_TYPE=Release -DCMAKE_CXX_FLAGS_RELEASE="-O1 -g"
cmake --build "$build" -j"$(nproc)"
# halt_on_error: a report fails the test; detect_leaks: leaks are findings too.
export ASAN_OPTIONS=halt_on_error=1:detect_leaks=1:abort_on_error=0
export UBSAN_OPTIONS=halt_on_error=1:print_stacktrace=1
ctest --test-dir "$build" --output-on-failure -j"$(nproc)" -LE 'rtl|formal|fuzz|install|hostile|long'
