#!/usr/bin/env bash
# Wall-clock times of a few rtl runs, best of N (default 5): two scene renders and three
# co-simulations (golden included). For comparing builds (docs/performance.md): run it against
# each build directory in turn.
#
#   scripts/rtl_speed.sh [BUILD_DIR] [RUNS]
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
build=$(cd "${1:-$root/build}" && pwd)
runs=${2:-5}
out=$(mktemp -d)
trap 'rm -rf "$out"' EXIT

best() {
  local best=
  for ((i = 0; i < runs; i++)); do
    local start end
    start=$(date +%s.%N)
    "$@" >/dev/null
    end=$(date +%s.%N)
    best=$(awk -v a="$start" -v b="$end" -v m="$best" 'BEGIN { t = b - a; print (m == "" || t < m) ? t : m }')
  done
  printf '%.2f s' "$best"
}

texsim=$build/tb/texsim
echo "render grazing, rtl      $(best "$texsim" render "$root/scenes/grazing.json" --engine rtl --out "$out/g")"
echo "render default, rtl      $(best "$texsim" render "$root/scenes/default.json" --engine rtl --out "$out/d")"
for block in trilinear footprint material; do
  printf 'cosim %-18s %s\n' "$block, rtl" \
    "$(best "$texsim" cosim "$block" --engines rtl --count 100000 --no-x-check --wave-dir "$out/w")"
done
