#!/usr/bin/env bash
# verilator --lint-only -Wall on every block of rtl/manifest.txt (its sources resolved by
# scripts/manifest_sources.sh, after tmu_pkg.sv and the handshake checker the blocks' files
# bind); fails on any warning.
set -euo pipefail
scripts=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rtl=$(cd "$scripts/../rtl" && pwd)

status=0
tops=$("$scripts/manifest_sources.sh")
for top in $tops; do
  files=("$rtl/tmu_pkg.sv" "$rtl/common/tmu_stream_check.sv")
  sources=$("$scripts/manifest_sources.sh" "$top")
  for s in $sources; do files+=("$rtl/$s"); done
  if verilator --lint-only -Wall --top-module "$top" "${files[@]}"; then
    echo "lint: $top clean"
  else
    echo "lint: $top FAILED"
    status=1
  fi
done
exit $status
