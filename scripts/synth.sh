#!/usr/bin/env bash
# Synthesizes every block of rtl/manifest.txt with Yosys: fails on latches or on any
# problem `check -assert` finds, and prints two cell counts per block (generic gates):
#   cells      every memory mapped to flip-flops (what an FPGA without RAM blocks would get)
#   logic      memories kept as RAM macros ($mem cells), the logic around them only
#   depth      logic depth: the longest path of gates between flops and ports (Yosys ltp -noff)
# and, for a block with submodules, the cells of each submodule (memories as flops).
# Usage: scripts/synth.sh [-G NAME=VALUE ...] [TOP...]   (default: every block)
#   -G overrides a parameter of the top (e.g. -G WeightBits=6), as the accuracy sweep does.
set -euo pipefail
rtl=$(cd "$(dirname "${BASH_SOURCE[0]}")/../rtl" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

count() { awk '/Number of cells:/ {n=$4} END {print n}' "$1"; }
count_type() { awk -v t="$2" '$1 == t {n+=$2} END {print n+0}' "$1"; }

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
while read -r top sources; do
  [[ -z "$top" || "$top" == \#* ]] && continue
  [[ ${#tops[@]} -gt 0 && ! " ${tops[*]} " =~ " $top " ]] && continue
  set_params=""
  for p in "${params[@]}"; do set_params+=" chparam -set ${p%%=*} ${p#*=} $top;"; done
  read_cmd="read_verilog -sv $rtl/tmu_pkg.sv"
  for s in $sources; do read_cmd+=" $rtl/$s"; done
  read_cmd+=";$set_params hierarchy -top $top"
  # Latches are checked right after proc, where an inferred latch is a $dlatch cell.
  if ! yosys -q -l "$work/$top.log" -p "$read_cmd; hierarchy -check -top $top; proc;
      select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; tee -q -o $work/$top.mem stat;
      synth -top $top -flatten; check -assert; tee -q -o $work/$top.full stat;
      tee -q -o $work/$top.ltp ltp -noff;
      design -reset; $read_cmd; synth -top $top -flatten -run begin:fine; opt -full;
      techmap; opt -fast; abc; opt_clean;
      tee -q -o $work/$top.logic stat"; then
    echo "synth: $top FAILED (latch or check error), log:"
    tail -20 "$work/$top.log"
    status=1
    continue
  fi
  flops=$(grep -E '\$_(S?DFF|DFFE|SDFFE|SDFFCE|ALDFF|DFFSR)' "$work/$top.full" | awk '{n+=$2} END {print n+0}')
  mem_bits=$(awk '/Number of memory bits:/ {n=$5} END {print n+0}' "$work/$top.mem")
  depth=$(sed -n 's/.*(length=\([0-9]*\)).*/\1/p' "$work/$top.ltp")
  printf "%-28s %10s %10s %10s %12s %6s\n" "$top" "$(count "$work/$top.full")" "$flops" \
    "$(count "$work/$top.logic")" "$mem_bits" "$depth"
  if [[ $(wc -w <<<"$sources") -gt 1 ]]; then  # per submodule, from a hierarchical synthesis
    yosys -q -p "$read_cmd; synth -top $top; tee -q -o $work/$top.hier stat"
    awk -v top="$top" '/^=== / {m=$2} /Number of cells:/ && m != "" && m != top && m != "design" && !seen[m]++ {
      printf "  %-26s %10s\n", m, $4}' "$work/$top.hier"
  fi
done < "$rtl/manifest.txt"
exit $status
