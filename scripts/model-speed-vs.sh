#!/usr/bin/env bash
# The model's single-threaded speed at two commits, built and run side by side on this machine:
# each commit is checked out into its own worktree and `rastersim` built there (Release, without
# the RTL backends), then `rastersim bench` runs the two builds in turn, pair by pair, on the same
# input. Prints each build's median fragments per second and the median of the per-pair ratios,
# which a load that drifts during the run moves least.
# Usage: scripts/model-speed-vs.sh [--pairs N] [--work DIR] COMMIT_A COMMIT_B [-- BENCH_ARGS...]
#   default BENCH_ARGS: the 20,000 triangles of 60 px at 1024 x 1024 (docs/performance.md);
#   default --pairs 9; worktrees and builds go to DIR (default $TMPDIR/rastersim-speed-vs, outside
#   the checkout), kept for reruns; `git worktree prune` forgets them once DIR is deleted.
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
pairs=9
work="${TMPDIR:-/tmp}/rastersim-speed-vs"
commits=()
bench_args=(--triangles 20000 --size 60 --width 1024 --height 1024 --cull none)
while [ $# -gt 0 ]; do
  case "$1" in
    --pairs) pairs="$2"; shift 2 ;;
    --work) work="$(realpath -m "$2")"; shift 2 ;;
    --) shift; bench_args=("$@"); break ;;
    -*) echo "model-speed-vs: unknown option $1" >&2; exit 2 ;;
    *) commits+=("$1"); shift ;;
  esac
done
if [ "${#commits[@]}" -ne 2 ]; then
  echo "usage: scripts/model-speed-vs.sh [--pairs N] [--work DIR] COMMIT_A COMMIT_B [-- BENCH_ARGS...]" >&2
  exit 2
fi
case "$pairs" in ''|*[!0-9]*|0) echo "model-speed-vs: --pairs needs a positive whole number" >&2; exit 2 ;; esac
mkdir -p "$work"

# build COMMIT: prints the path of that commit's rastersim.
build() {
  local hash tree
  hash="$(git -C "$root" rev-parse --verify --quiet "$1^{commit}")" || { echo "model-speed-vs: no commit $1" >&2; exit 2; }
  tree="$work/$hash"
  [ -d "$tree" ] || git -C "$root" worktree add --detach "$tree" "$hash" > /dev/null 2>&1
  cmake -S "$tree" -B "$tree/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_DISABLE_FIND_PACKAGE_verilator=ON \
    > "$tree/configure.log" 2>&1
  echo "building $1 ($hash) in $tree/build" >&2
  cmake --build "$tree/build" -j2 --target rastersim > "$tree/build.log" 2>&1 ||
    { echo "model-speed-vs: the build of $1 failed: $tree/build.log" >&2; exit 1; }
  echo "$tree/build/rastersim"
}
a="$(build "${commits[0]}")"
b="$(build "${commits[1]}")"

# One thread at either commit: builds that have --threads get --threads 1.
# (The help is read whole first: grep -q would close the pipe early, and pipefail would call it absent.)
args_for() {
  local help
  help="$("$1" bench --help)"
  if grep -q -- '--threads' <<< "$help"; then echo "--threads 1"; fi
}
read -r -a a_extra <<< "$(args_for "$a")"
read -r -a b_extra <<< "$(args_for "$b")"
speed() { "$@" | awk '/^fragments/ { gsub(",", "", $3); print $3 }'; }
echo "machine: $(nproc) cores; $(uptime | sed 's/.*load/load/')"
echo "input: ${bench_args[*]}; $pairs pairs, each run the best of 11 repetitions"
echo "${commits[0]}: bench ${a_extra[*]:-(one thread only)}; ${commits[1]}: bench ${b_extra[*]:-(one thread only)}"
results="$work/pairs.txt"
: > "$results"
for _ in $(seq "$pairs"); do
  fa="$(speed "$a" bench "${bench_args[@]}" --repeat 11 "${a_extra[@]}")"
  fb="$(speed "$b" bench "${bench_args[@]}" --repeat 11 "${b_extra[@]}")"
  [ -n "$fa" ] && [ -n "$fb" ] || { echo "model-speed-vs: a bench run printed no speed" >&2; exit 1; }
  echo "$fa $fb" >> "$results"
done
sort_median() { sort -g | awk '{ v[NR] = $1 } END { print (NR % 2) ? v[(NR + 1) / 2] : (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
ma="$(awk '{ print $1 }' "$results" | sort_median)"
mb="$(awk '{ print $2 }' "$results" | sort_median)"
ratio="$(awk '{ print $1 / $2 }' "$results" | sort_median)"
low="$(awk '{ print $1 / $2 }' "$results" | sort -g | head -1)"
high="$(awk '{ print $1 / $2 }' "$results" | sort -g | tail -1)"
printf '%s: %.4g fragments per second (median)\n' "${commits[0]}" "$ma"
printf '%s: %.4g fragments per second (median)\n' "${commits[1]}" "$mb"
printf '%s / %s: %.3f (median of the pairs; %.3f .. %.3f)\n' "${commits[0]}" "${commits[1]}" "$ratio" "$low" "$high"
