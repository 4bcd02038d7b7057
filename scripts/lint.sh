#!/usr/bin/env bash
# verilator --lint-only -Wall on every block of rtl/manifest.txt; fails on any warning.
set -euo pipefail
rtl=$(cd "$(dirname "${BASH_SOURCE[0]}")/../rtl" && pwd)

status=0
while read -r top sources; do
  [[ -z "$top" || "$top" == \#* ]] && continue
  files=("$rtl/tmu_pkg.sv")
  for s in $sources; do files+=("$rtl/$s"); done
  if verilator --lint-only -Wall --top-module "$top" "${files[@]}"; then
    echo "lint: $top clean"
  else
    echo "lint: $top FAILED"
    status=1
  fi
done < "$rtl/manifest.txt"
exit $status
