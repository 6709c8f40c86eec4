#!/usr/bin/env bash
# Docs and sources state the design as it is; its history is git log's. This check finds lines
# that narrate the project's history by numbered work rounds ("session 16", "rounds 3 and 4",
# "session 18's walker", "this session", "the first round's unit") in README.md, docs/ and the
# sources (the generated packages in vectors/ and this script excluded), prints each as
# FILE:LINE: TEXT and exits 1; with none it prints "no history narration" and exits 0.
# Usage: tests/docs_history_check.sh [ROOT]   (default: the repository this script is in)
set -euo pipefail
root="$(cd "${1:-$(dirname "$0")/..}" && pwd)"
self="tests/docs_history_check.sh"
pattern='\bsessions? [0-9]+|\brounds? [0-9]+|\bsession [0-9]+.s\b|\b(this|last|earlier|previous) (session|round)s?\b|\bfirst round\b'
cd "$root"
paths=()
for p in README.md docs model rtl testbench cli fast frontend api scripts tests python examples bench cmake; do
  [ -e "$p" ] && paths+=("$p")
done
# -I: text files only (images and other binaries are skipped).
hits="$(grep -rnIiE "$pattern" "${paths[@]}" | grep -v "^$self:" || true)"
if [ -n "$hits" ]; then
  printf '%s\n' "$hits"
  echo "docs_history_check: the lines above narrate history by numbered rounds; state the design as it is (history belongs to git log)" >&2
  exit 1
fi
echo "no history narration"
