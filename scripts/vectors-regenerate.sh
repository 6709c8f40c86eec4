#!/usr/bin/env bash
# Regenerates the checked-in test-vector packages (vectors/NAME for every line of
# vectors/packages.txt) with a built rastersim. With --check, regenerates them into a scratch
# folder instead and fails unless every file is byte-identical to the checked-in one.
# Usage: scripts/vectors-regenerate.sh [--check] [RASTERSIM]   (default: build/rastersim)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
check=0
if [ "${1:-}" = "--check" ]; then
  check=1
  shift
fi
exe="${1:-$root/build/rastersim}"
if [ $check -eq 1 ]; then
  out="$(mktemp -d)"
  trap 'rm -rf "$out"' EXIT
else
  out="$root/vectors"
fi
status=0
names=()
while read -r name args; do
  case "$name" in '' | '#'*) continue ;; esac
  names+=("$name")
  # shellcheck disable=SC2086  # args is a list of words
  if ! "$exe" vectors $args --rtl-path ../../rtl --testbench-path ../../testbench/vectors --out "$out/$name" --force > /dev/null; then
    echo "vectors-regenerate: rastersim vectors failed for $name" >&2
    status=1
    continue
  fi
  if [ $check -eq 1 ]; then
    if ! diff -r "$root/vectors/$name" "$out/$name" > "$out/$name.diff" 2>&1; then
      echo "vectors/$name is not what this build generates:"
      head -n 20 "$out/$name.diff"
      status=1
    fi
  else
    echo "vectors/$name"
  fi
done < "$root/vectors/packages.txt"
for dir in "$root"/vectors/*/; do
  name="$(basename "$dir")"
  case " ${names[*]} " in
    *" $name "*) ;;
    *)
      echo "vectors/$name is not listed in vectors/packages.txt"
      status=1
      ;;
  esac
done
if [ $status -ne 0 ] && [ $check -eq 1 ]; then
  echo "regenerate them with: scripts/vectors-regenerate.sh $exe"
fi
[ $status -eq 0 ] && [ $check -eq 1 ] && echo "vectors-regenerate: ${#names[@]} packages regenerate byte-identical"
exit $status
