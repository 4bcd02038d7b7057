#!/usr/bin/env bash
# rtl/manifest.txt resolved, for the scripts (lint.sh, synth.sh); the format is described at
# the top of the manifest. rtl/CMakeLists.txt and tb/icarus/icarus_engine.cpp resolve it the
# same way.
#
# Usage: scripts/manifest_sources.sh          every top, one a line, in the manifest's order
#        scripts/manifest_sources.sh TOP      TOP's sources relative to rtl/, one a line, each
#                                             once, in dependency order (tmu_pkg.sv, always
#                                             read first, is not among them)
# Fails (exit 1, a message on stderr) on an unknown TOP, an item that is neither a .sv file
# nor the top of an earlier row, a missing file or a top with two rows.
set -euo pipefail
rtl=$(cd "$(dirname "${BASH_SOURCE[0]}")/../rtl" && pwd)
manifest="$rtl/manifest.txt"

fail() { echo "manifest_sources: $manifest: $*" >&2; exit 1; }

declare -A resolved  # top -> its sources, space separated
tops=()
while read -r top items; do
  [[ -z "$top" || "$top" == \#* ]] && continue
  [[ -v "resolved[$top]" ]] && fail "$top has two rows"
  unset seen
  declare -A seen=()
  sources=()
  for item in $items; do
    if [[ "$item" == *.sv ]]; then
      [[ -f "$rtl/$item" ]] || fail "$top: $item does not exist"
      files=("$item")
    elif [[ -v "resolved[$item]" ]]; then
      read -ra files <<<"${resolved[$item]}"
    else
      fail "$top: $item is neither a .sv file nor the top of an earlier row"
    fi
    for f in "${files[@]}"; do
      [[ -v "seen[$f]" ]] && continue
      seen[$f]=1
      sources+=("$f")
    done
  done
  resolved[$top]="${sources[*]}"
  tops+=("$top")
done < "$manifest"

if [[ $# -eq 0 ]]; then
  printf '%s\n' "${tops[@]}"
else
  [[ -v "resolved[$1]" ]] || fail "$1 is not a top"
  printf '%s\n' ${resolved[$1]}
fi
