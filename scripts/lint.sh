#!/usr/bin/env bash
# verilator --lint-only -Wall on every block of rtl/manifest.txt (its sources resolved by
# scripts/manifest_sources.sh, after tmu_pkg.sv and the handshake checker, and then the top's
# stream-check binds generated from its block description); fails on any warning.
set -euo pipefail
scripts=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
rtl=$(cd "$scripts/../rtl" && pwd)
generated=$(mktemp -d)
trap 'rm -rf "$generated"' EXIT
python3 "$scripts/gen_block_descriptions.py" "$generated" "$scripts"/../tb/blocks/*/*.json

status=0
tops=$("$scripts/manifest_sources.sh")
for top in $tops; do
  files=("$rtl/tmu_pkg.sv" "$rtl/common/tmu_stream_check.sv")
  sources=$("$scripts/manifest_sources.sh" "$top")
  for s in $sources; do files+=("$rtl/$s"); done
  binds="$generated/rtl/${top}_binds.sv"
  if [[ -f "$binds" ]]; then files+=("$binds"); fi
  if verilator --lint-only -Wall --top-module "$top" "${files[@]}"; then
    echo "lint: $top clean"
  else
    echo "lint: $top FAILED"
    status=1
  fi
done
exit $status
