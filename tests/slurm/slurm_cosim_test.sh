#!/usr/bin/env bash
# ctest slurm.cosim_job_array (label slurm): scripts/slurm-cosim.sh on the Slurm cluster this machine
# submits to runs the shards of a cosim run as a job array and merges them; the merged JUnit file
# holds exactly the frames of the same run unsharded. Skips (exit 77) where no cluster answers.
# Usage: slurm_cosim_test.sh RASTERSIM_EXE SOURCE_DIR
set -euo pipefail
exe="$1" root="$2"
if ! command -v sbatch > /dev/null || ! sinfo -h > /dev/null 2>&1; then
  echo "skipped: no Slurm cluster answers here (sbatch, sinfo); docs/regressions.md sets up a single node"
  exit 77
fi
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
run=(--count 10 --width 64 --height 48 --seed 5)
"$root/scripts/slurm-cosim.sh" --rastersim "$exe" --shards 3 --out "$work/array" --wait -- "${run[@]}"
"$exe" cosim "${run[@]}" --junit "$work/all.xml" > /dev/null
python3 - "$work/array/cosim.xml" "$work/all.xml" <<'PY'
import re, sys
def frames(path):
    return sorted(re.findall(r'<testcase classname="rastersim.cosim" name="([^"]*)"', open(path).read()))
merged, whole = frames(sys.argv[1]), frames(sys.argv[2])
if not merged or merged != whole:
    sys.exit(f"the job array's merged JUnit has {len(merged)} frames, the unsharded run {len(whole)}; they differ")
print(f"job array: {len(merged)} frames, the same as the unsharded run")
PY
