#!/usr/bin/env bash
# Synthesizes every block of rtl/manifest.txt with Yosys: fails on latches or on any
# problem `check -assert` finds, and prints per block (generic gates):
#   cells        every memory mapped to flip-flops (what an FPGA without RAM blocks would get)
#   flops        flip-flops among those cells
#   logic        memories kept as RAM macros ($mem cells): the logic around them only
#   memory_bits  bits of those memories
#   depth        logic depth of that netlist: the longest path of gates between flops, RAM
#                ports and block ports (Yosys ltp -noff)
# and, for a block with submodules, the logic cells of each submodule.
# Usage: scripts/synth.sh [-G NAME=VALUE ...] [TOP...]   (default: every block)
#   -G overrides a parameter of the top (e.g. -G WeightBits=6), as the accuracy sweep does.
set -euo pipefail
rtl=$(cd "$(dirname "${BASH_SOURCE[0]}")/../rtl" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() { awk '/Number of cells:/ {n=$4} END {print n}' "$1"; }

params=()
tops=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    -G) params+=("$2"); shift 2 ;;
    *) tops+=("$1"); shift ;;
  esac
done

printf "%-28s %10s %10s %10s %12s %6s\n" block cells flops logic memory_bits depth
status=0
manifest="$(dirname "${BASH_SOURCE[0]}")/manifest_sources.sh"  # rtl/manifest.txt resolved
manifest_tops=$("$manifest")
for top in $manifest_tops; do
  [[ ${#tops[@]} -gt 0 && ! " ${tops[*]} " =~ " $top " ]] && continue
  sources=$("$manifest" "$top")
  read_cmd="read_verilog -sv $rtl/tmu_pkg.sv"
  for s in $sources; do read_cmd+=" $rtl/$s"; done
  read_cmd+=";"
  for p in "${params[@]}"; do read_cmd+=" chparam -set ${p%%=*} ${p#*=} $top;"; done
  read_cmd+=" hierarchy -check -top $top"
  # Logic to gates with memories left as $mem cells (the RAM macros of a real chip).
  to_logic="opt -full; techmap; opt -fast; abc; opt_clean"
  # Latches are checked right after proc, where an inferred latch is a $dlatch cell.
  if ! yosys -q -l "$work/$top.log" -p "$read_cmd; proc;
      select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; tee -q -o $work/$top.mem stat;
      synth -top $top -flatten; check -assert; tee -q -o $work/$top.full stat;
      design -reset; $read_cmd; synth -top $top -flatten -run begin:fine; $to_logic;
      tee -q -o $work/$top.logic stat; tee -q -o $work/$top.ltp ltp -noff"; then
    echo "synth: $top FAILED (latch or check error), log:"
    tail -20 "$work/$top.log"
    status=1
    continue
  fi
  flops=$(awk '/\$_(S?DFF|DFFE|SDFFE|SDFFCE|ALDFF|DFFSR)/ {n+=$2} END {print n+0}' "$work/$top.full")
  mem_bits=$(awk '/Number of memory bits:/ {n=$5} END {print n+0}' "$work/$top.mem")
  depth=$(sed -n 's/.*(length=\([0-9]*\)).*/\1/p' "$work/$top.ltp")
  printf "%-28s %10s %10s %10s %12s %6s\n" "$top" "$(count "$work/$top.full")" "$flops" \
    "$(count "$work/$top.logic")" "$mem_bits" "$depth"
  if [[ $(wc -w <<<"$sources") -gt 1 ]]; then  # logic per submodule, hierarchy kept
    yosys -q -p "$read_cmd; synth -top $top -run begin:fine; $to_logic; tee -q -o $work/$top.hier stat"
    # Yosys names a parameterised module $paramod\NAME\PARAM=... or $paramod$HASH\NAME.
    awk -v top="$top" '/^=== / {m=$2} /Number of cells:/ && m != "" && m != top && m != "design" && !seen[m]++ {
        name = m; sub(/^\$paramod(\$[0-9a-f]+)?\\/, "", name); sub(/\\.*/, "", name)
        if (!(name in cells)) order[n++] = name
        cells[name] += $4; variants[name]++ }
      END { for (i = 0; i < n; i++) { v = variants[order[i]] > 1 ? " (" variants[order[i]] " variants)" : ""
              printf "  %-26s %10s%s\n", order[i], cells[order[i]], v } }' "$work/$top.hier"
  fi
done
exit $status
