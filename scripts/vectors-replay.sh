#!/usr/bin/env bash
# Replays test-vector packages against rtl/: runs each package's run_icarus.sh (or, with
# --verilator, run_verilator.sh) and fails unless every one ends with "N passed, 0 failed".
# Usage: scripts/vectors-replay.sh [--verilator] [PACKAGE_DIR...]   (default: every vectors/*/)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
runner=run_icarus.sh
if [ "${1:-}" = "--verilator" ]; then
  runner=run_verilator.sh
  shift
fi
packages=("$@")
if [ ${#packages[@]} -eq 0 ]; then
  packages=("$root"/vectors/*/)
fi
status=0
for package in "${packages[@]}"; do
  package="${package%/}"
  if summary="$("$package/$runner" 2>&1 | tail -n 1)" && [[ "$summary" =~ ^[0-9]+\ passed,\ 0\ failed$ ]]; then
    echo "$(basename "$package"): $summary"
  else
    echo "$(basename "$package"): FAILED ($runner: $summary)"
    status=1
  fi
done
exit $status
