#!/usr/bin/env bash
# Installs what is missing, builds, and renders the default built-in scene through the model and the
# RTL in lockstep (--backend cosim: every fragment, buffer word and cycle compared), writing the
# images to out/ and printing the stats.
set -euo pipefail
cd "$(dirname "$0")/.."
scripts/install-deps.sh
cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
cmake --build build -j"$(nproc)" --target rastersim
mkdir -p out
./build/rastersim render --backend cosim -o out/color.png --depth-out out/depth.exr --fragments out/fragments.csv \
  --stats out/stats.json "$@"
echo "wrote out/color.png out/depth.exr out/fragments.csv out/stats.json"
