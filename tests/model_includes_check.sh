#!/usr/bin/env bash
# model/ is the plain specification: its files include only model/ and system headers, nothing of
# fast/, testbench/ or cli/ (by those folders' paths, by a relative path into them, or by the name
# of one of their headers). Prints each offending include as file:line and exits 1.
# Usage: tests/model_includes_check.sh [source root]   (default: this script's repository)
set -euo pipefail

root=$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/..}" && pwd)
cd "$root"
[[ -d model ]] || { echo "no model/ folder under $root" >&2; exit 2; }
forbidden=(fast testbench cli)

# Paths (from the root) of every file in the forbidden folders, to match includes by name.
forbidden_files=$(find "${forbidden[@]}" -type f 2>/dev/null || true)

in_forbidden() {  # a path relative to the root
  local f
  for f in "${forbidden[@]}"; do [[ $1 == "$f"/* ]] && return 0; done
  return 1
}

failed=0
while IFS= read -r -d '' file; do
  line_number=0
  while IFS= read -r line || [[ -n $line ]]; do
    line_number=$((line_number + 1))
    [[ $line =~ ^[[:space:]]*#[[:space:]]*include(_next)?[[:space:]]*[\"\<]([^\"\>]+)[\"\>] ]] || continue
    included=${BASH_REMATCH[2]}
    bad=0
    # By the folder's path, or a relative one that leads into it (model/../fast/x.h, ../cli/x.h).
    resolved=$(realpath -m --relative-to="$root" "$(dirname "$file")/$included")
    from_root=$(realpath -m --relative-to="$root" "$root/$included")
    if in_forbidden "$from_root" || in_forbidden "$resolved"; then
      bad=1
    elif [[ ! -e $resolved && ! -e $from_root ]]; then
      # Not a model/ file: by the name of one of the forbidden folders' files (found through an
      # include path into them)?
      while IFS= read -r candidate; do
        [[ -n $candidate && ( $candidate == "$included" || $candidate == */"$included" ) ]] && bad=1 && break
      done <<<"$forbidden_files"
    fi
    if ((bad)); then
      echo "$file:$line_number: $line"
      failed=1
    fi
  done <"$file"
done < <(find model -type f -print0 | sort -z)

if ((failed)); then
  echo "model/ must include only model/ and system headers, nothing of ${forbidden[*]/%//}" >&2
  exit 1
fi
echo "model/ includes only model/ and system headers"
