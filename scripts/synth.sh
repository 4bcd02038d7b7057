#!/usr/bin/env bash
# Yosys on every block of rtl/manifest.txt (docs/synth.md), in two modes.
#
# scripts/synth.sh [-G NAME=VALUE ...] [TOP...]   the check: seconds a block; ctest rtl_synth_<top>
#   Reads and elaborates the top (hierarchy -check: every module, port and parameter resolves),
#   fails on an inferred latch (a $dlatch cell right after proc) and on any problem
#   `check -assert` finds on the flattened netlist after proc: two drivers of one bit, a wire
#   read but never driven, a combinational loop. That is where `synth` runs its own check; the
#   mapping after it (opt, memory, techmap, abc), minutes for the large blocks, only counts gates.
#   Shown to fail, on broken copies of rtl/: in tmu_ccc_decoder an `always @*` assigning index
#   in one branch only (latch), a second assign of req_ready_o from a gate (two drivers),
#   clut_ready_o read from a wire nothing drives, req_ready_o fed back through req_fire (loop);
#   in tmu_ccc_cache_bilinear a loop through the submodule u_axis_u, found only because the
#   netlist is flattened. Yosys 0.23's check finds at no point of the flow (nor does
#   Verilator's lint) a second driver that is a constant: `assign x = 1'b0;` beside a gate.
#
# scripts/synth.sh --figures [-G NAME=VALUE ...] [TOP...]   the full synthesis: minutes a block
#   The same checks, `check -assert` again after the flattened `synth`, and per block (generic
#   gates; `texsim sweep all` and scripts/synth_doc.sh read these):
#     cells        every memory mapped to flip-flops (what an FPGA without RAM blocks would get)
#     flops        flip-flops among those cells
#     logic        memories kept as RAM macros ($mem cells): the logic around them only
#     memory_bits  bits of those memories
#     depth        logic depth of that netlist: the longest path of gates between flops, RAM
#                  ports and block ports (Yosys ltp -noff)
#     yosys_s      wall seconds Yosys took when the figures were made (not when read back)
#   and, for a block with submodules, the logic cells of each submodule (--no-submodules leaves
#   them out: one Yosys run less, what the accuracy sweep asks for). Both netlists take the same
#   steps to gates, so cells - logic is the memories alone; a block without memories is
#   synthesized once (logic = cells).
#   Figures are cached by a content key: the top, the -G parameters, the Yosys version, this
#   script and every source file the top reads. A cached top prints at once (and says so on
#   stderr). The cache is $TMU_SYNTH_CACHE, default ${TMU_BUILD_DIR:-build}/synth_cache/.
#
# scripts/synth.sh --list   the tops, one a line (what scripts/synth_doc.sh runs)
#
# -G overrides a parameter of the top (e.g. -G WeightBits=6), as the accuracy sweep does.
# Exit: 0 clean, 1 a block failed, 2 bad arguments (an unknown option or top).
set -euo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
rtl=$root/rtl
cache=${TMU_SYNTH_CACHE:-${TMU_BUILD_DIR:-$root/build}/synth_cache}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

usage() { awk 'NR > 1 && !/^#/ {exit} NR > 1 {sub(/^# ?/, ""); print}' "${BASH_SOURCE[0]}"; }
bad() { echo "synth.sh: $1 (--help for usage)" >&2; exit 2; }

figures=0
list=0
submodules=1
params=()
tops=()
while [[ $# -gt 0 ]]; do
  case "$1" in
    --figures) figures=1; shift ;;
    --list) list=1; shift ;;
    --no-submodules) submodules=0; shift ;;
    -G)
      [[ $# -ge 2 && "$2" == [A-Za-z_]*=* ]] || bad "-G needs NAME=VALUE"
      params+=("$2"); shift 2 ;;
    -h | --help) usage; exit 0 ;;
    -*) bad "unknown option '$1'" ;;
    *) tops+=("$1"); shift ;;
  esac
done

count() { awk '/Number of cells:/ {n=$4} END {print n}' "$1"; }

# Prints the failing block's problems (Yosys's warnings with their detail lines, and its
# errors; the end of the log when there are none) and keeps the log.
report_failure() {
  echo "synth: $1 FAILED ($2), log $work/$1.log:"
  local problems
  problems=$(awk '/^(Warning|ERROR)/ {p = 1; print; next} p && /^ / {print; next} {p = 0}' "$work/$1.log")
  if [[ -n "$problems" ]]; then head -30 <<<"$problems"; else tail -20 "$work/$1.log"; fi
  trap - EXIT
}

# The check of one top: elaborate, no latch, check -assert on the flattened coarse netlist.
check_top() {
  local top=$1 read_cmd=$2 start=$SECONDS
  if ! yosys -q -l "$work/$top.log" -p "$read_cmd; proc;
      select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr;
      flatten; opt_expr; opt_clean; check -assert" >/dev/null 2>&1; then
    report_failure "$top" "elaboration, a latch or a check problem"
    return 1
  fi
  echo "synth: $top: elaborated, no latch, check clean ($((SECONDS - start)) s)"
}

# The content key of a top's figures. The sources are the files of its read command.
figures_key() {
  local top=$1 read_cmd=$2 files
  files=${read_cmd%%;*}
  files=${files#read_verilog -sv }
  {
    echo "$top submodules=$submodules"
    printf '%s\n' "${params[@]}"
    yosys -V
    cat "${BASH_SOURCE[0]}"
    for f in $files; do echo "${f#"$rtl"/}"; cat "$f"; done
  } | sha256sum | cut -c1-16
}

# The full synthesis of one top: its table row and submodule lines, from the cache or Yosys.
# (Called before `||`, where bash ignores set -e: every Yosys run is tested explicitly.)
figures_top() {
  local top=$1 read_cmd=$2 sources=$3 start=$SECONDS
  local entry
  entry="$cache/$top-$(figures_key "$top" "$read_cmd").txt"
  if [[ -s "$entry" ]]; then
    cat "$entry"
    echo "synth: $top: from cache $entry" >&2
    return 0
  fi
  # Latches are checked right after proc, where an inferred latch is a $dlatch cell.
  if ! yosys -q -l "$work/$top.log" -p "$read_cmd; proc;
      select -assert-none t:\$dlatch t:\$adlatch t:\$dlatchsr; tee -q -o $work/$top.mem stat" \
      >/dev/null 2>&1; then
    report_failure "$top" "a latch"
    return 1
  fi
  local mem_bits
  mem_bits=$(awk '/Number of memory bits:/ {n=$5} END {print n+0}' "$work/$top.mem")
  # The coarse synthesis, then to gates: both netlists take the same steps (abc at full effort),
  # so cells - logic is the memories and nothing else. Without memories the two are one netlist,
  # made once (the second run is minutes for the wide multipliers).
  # synth's own fine steps, with abc at full effort (synth runs abc -fast).
  local coarse="$read_cmd; synth -top $top -flatten -run begin:fine; opt -fast -full"
  local to_gates="opt -full; techmap; opt -fast; abc; opt -fast"
  local depth_of="tee -q -o $work/$top.ltp ltp -noff"
  local logic_pass="design -reset; $coarse; $to_gates; tee -q -o $work/$top.logic stat; $depth_of"
  if ((mem_bits == 0)); then logic_pass=$depth_of; fi
  if ! yosys -q -l "$work/$top.log" -p "$coarse; memory_map; $to_gates; check -assert;
      tee -q -o $work/$top.full stat; $logic_pass" >/dev/null 2>&1; then
    report_failure "$top" "a check error"
    return 1
  fi
  ((mem_bits == 0)) && cp "$work/$top.full" "$work/$top.logic"
  local flops depth
  flops=$(awk '/\$_(S?DFF|DFFE|SDFFE|SDFFCE|ALDFF|DFFSR)/ {n+=$2} END {print n+0}' "$work/$top.full")
  depth=$(sed -n 's/.*(length=\([0-9]*\)).*/\1/p' "$work/$top.ltp")
  : >"$work/$top.sub"
  if ((submodules)) && [[ $(wc -w <<<"$sources") -gt 1 ]]; then  # logic per submodule
    if ! yosys -q -l "$work/$top.log" -p "$read_cmd; synth -top $top -run begin:fine; opt -fast -full; $to_gates;
        tee -q -o $work/$top.hier stat" >/dev/null 2>&1; then
      report_failure "$top" "the synthesis with hierarchy kept"
      return 1
    fi
    # Yosys names a parameterised module $paramod\NAME\PARAM=... or $paramod$HASH\NAME.
    awk -v top="$top" '/^=== / {m=$2} /Number of cells:/ && m != "" && m != top && m != "design" && !seen[m]++ {
        name = m; sub(/^\$paramod(\$[0-9a-f]+)?\\/, "", name); sub(/\\.*/, "", name)
        if (!(name in cells)) order[n++] = name
        cells[name] += $4; variants[name]++ }
      END { for (i = 0; i < n; i++) { v = variants[order[i]] > 1 ? " (" variants[order[i]] " variants)" : ""
              printf "  %-26s %10s%s\n", order[i], cells[order[i]], v } }' "$work/$top.hier" >"$work/$top.sub"
  fi
  printf "%-28s %10s %10s %10s %12s %6s %8s\n" "$top" "$(count "$work/$top.full")" "$flops" \
    "$(count "$work/$top.logic")" "$mem_bits" "$depth" "$((SECONDS - start))" >"$work/$top.row"
  cat "$work/$top.sub" >>"$work/$top.row"
  cat "$work/$top.row"
  # Written whole and renamed, so that parallel runs (synth_doc.sh) never read half an entry.
  mkdir -p "$cache"
  cp "$work/$top.row" "$entry.$$" && mv "$entry.$$" "$entry"
}

((figures && !list)) &&
  printf "%-28s %10s %10s %10s %12s %6s %8s\n" block cells flops logic memory_bits depth yosys_s
status=0
seen=()
manifest=$root/scripts/manifest_sources.sh  # rtl/manifest.txt's rows resolved
for top in $("$manifest"); do
  [[ ${#tops[@]} -gt 0 && ! " ${tops[*]} " =~ " $top " ]] && continue
  seen+=("$top")
  ((list)) && { echo "$top"; continue; }
  sources=$("$manifest" "$top")
  read_cmd="read_verilog -sv $rtl/tmu_pkg.sv"
  for s in $sources; do read_cmd+=" $rtl/$s"; done
  read_cmd+=";"
  for p in "${params[@]}"; do read_cmd+=" chparam -set ${p%%=*} ${p#*=} $top;"; done
  read_cmd+=" hierarchy -check -top $top"
  if ((figures)); then
    figures_top "$top" "$read_cmd" "$sources" || status=1
  else
    check_top "$top" "$read_cmd" || status=1
  fi
done

for t in "${tops[@]}"; do
  [[ " ${seen[*]} " =~ " $t " ]] || bad "'$t' is not a top of rtl/manifest.txt"
done
exit $status
