#!/usr/bin/env bash
# A cosim regression as a Slurm job array (docs/regressions.md): N array tasks run the shards of one
# run (`rastersim cosim --shard K/N --junit`), then a job that depends on them all merges their JUnit
# files (`rastersim junit-merge`) into OUT/cosim.xml. Prints the job ids; with --wait it blocks until
# the merge is done and exits with its code (0: every frame passed, 1: a frame diverged).
# Usage: scripts/slurm-cosim.sh --shards N --out DIR [--rastersim EXE] [--wait] [--sbatch "ARGS"] \
#          [-- COSIM FLAGS...]
# Example: scripts/slurm-cosim.sh --shards 16 --out regression --wait -- --count 20000 --seed 7
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
rastersim="$root/build/rastersim"
shards="" out="" wait=0 sbatch_args=""
while [ $# -gt 0 ]; do
  case "$1" in
    --shards) shards="$2"; shift 2 ;;
    --out) out="$2"; shift 2 ;;
    --rastersim) rastersim="$2"; shift 2 ;;
    --wait) wait=1; shift ;;
    --sbatch) sbatch_args="$2"; shift 2 ;;
    --) shift; break ;;
    *) echo "slurm-cosim: unknown argument $1" >&2; exit 2 ;;
  esac
done
[[ "$shards" =~ ^[1-9][0-9]*$ ]] || { echo "slurm-cosim: --shards N (1 or more) is required" >&2; exit 2; }
[ -n "$out" ] || { echo "slurm-cosim: --out DIR is required" >&2; exit 2; }
[ -x "$rastersim" ] || { echo "slurm-cosim: $rastersim is not an executable (build first, or --rastersim EXE)" >&2; exit 2; }
command -v sbatch > /dev/null || { echo "slurm-cosim: sbatch not found: Slurm is not installed here" >&2; exit 2; }
mkdir -p "$out"
out="$(cd "$out" && pwd)"
rastersim="$(realpath "$rastersim")"
# The cosim flags, quoted for the job's shell.
flags=""
for f in "$@"; do flags+=" $(printf '%q' "$f")"; done

# shellcheck disable=SC2086  # sbatch_args: the user's extra sbatch options, split on purpose
array=$(sbatch --parsable $sbatch_args --job-name=rastersim-cosim --array="1-$shards" \
  --output="$out/shard-%a.log" --chdir="$out" \
  --wrap="$(printf '%q' "$rastersim") cosim$flags --shard \$SLURM_ARRAY_TASK_ID/$shards --junit shard-\$SLURM_ARRAY_TASK_ID.xml --replay-dir .")
array=${array%%;*}
inputs=""
for k in $(seq 1 "$shards"); do inputs+=" shard-$k.xml"; done
# afterany: merge whatever the shards wrote, failed shards included (a missing file is an error).
wait_flag=""
[ "$wait" = 1 ] && wait_flag="--wait"
set +e
# shellcheck disable=SC2086
merge=$(sbatch --parsable $sbatch_args $wait_flag --job-name=rastersim-merge --dependency="afterany:$array" \
  --output="$out/merge.log" --chdir="$out" \
  --wrap="$(printf '%q' "$rastersim") junit-merge -o cosim.xml$inputs")
status=$?
set -e
echo "slurm-cosim: shards job $array (array 1-$shards), merge job ${merge%%;*}; logs and JUnit files in $out"
[ "$wait" = 1 ] && { cat "$out/merge.log"; exit $status; }
exit 0
