#!/usr/bin/env bash
# The board self-test of a small whole-core configuration on an iCE40 HX8K (docs/performance.md,
# "The whole core on one iCE40 HX8K"): writes a test-vector package of the depth suite at the
# profile below, simulates its self-test in Icarus (it must print "selftest: PASS"), builds its
# bitstream with the package's build_selftest_hx8k.sh (yosys, nextpnr-ice40 seed 1, icepack) and
# fails unless it fits the device and its Fmax is at least MIN_MHZ (the documented figure).
# Usage: scripts/selftest-hx8k.sh [RASTERSIM] [MIN_MHZ]   (defaults: build/rastersim, 45)
# (Measured 49.1 MHz, docs/performance.md. Netlists that differ only in names
# and source paths move nextpnr's placement by 2 to 4 MHz, hence the margin below that figure.)
set -euo pipefail
root="$(cd "$(dirname "$0")/.." && pwd)"
exe="${1:-$root/build/rastersim}"
min_mhz="${2:-45}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# The small profile, the selftest-hx8k line of vectors/packages.txt: 32 x 24, S = 2, N = 16, the
# serial setup unit, memory latency 1, one record, flat shading. The self-test's configuration is
# constant, so synthesis removes what flat shading never uses (the colour plane registers and the
# setup's colour results): a Z-only board build.
read -r -a profile < <(awk '$1 == "selftest-hx8k" { $1 = ""; print }' "$root/vectors/packages.txt")
if [ ${#profile[@]} -eq 0 ]; then
  echo "selftest-hx8k: vectors/packages.txt has no selftest-hx8k line" >&2
  exit 2
fi
"$exe" vectors "${profile[@]}" --out "$work/package" > /dev/null
echo "selftest-hx8k: package: rastersim vectors ${profile[*]}"
if ! "$work/package/run_selftest_icarus.sh" > "$work/icarus.log" 2>&1; then
  cat "$work/icarus.log"
  echo "selftest-hx8k: the self-test does not pass in Icarus"
  exit 1
fi
grep '^selftest:' "$work/icarus.log"
if ! OUT="$work/hx8k" "$work/package/build_selftest_hx8k.sh" > "$work/build.log" 2>&1; then
  cat "$work/build.log"
  echo "selftest-hx8k: no bitstream (see above)"
  exit 1
fi
cat "$work/build.log"
cells=$(awk '/ICESTORM_LC:/ { sub("/", "", $3); print $3 }' "$work/hx8k/nextpnr.log" | tail -n 1)
mhz=$(grep -E "Max frequency for clock" "$work/hx8k/nextpnr.log" | tail -n 1 | sed -E 's/.*: ([0-9.]+) MHz.*/\1/')
echo "selftest-hx8k: $cells logic cells (of 7680), Fmax $mhz MHz (at least $min_mhz required)"
if ! awk -v f="$mhz" -v m="$min_mhz" 'BEGIN { exit !(f >= m) }'; then
  echo "selftest-hx8k: Fmax $mhz MHz is below the documented $min_mhz MHz"
  exit 1
fi
