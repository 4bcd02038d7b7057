# What the shell tests share; sourced by each as
#   source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
# with $1 the texsim binary. Sets texsim (its absolute path), root (the repository), work (a
# temporary directory, removed on exit) and failures; gives pass/fail (one line each, fail
# counts), column (a cell of $work/table.md), less (a numeric a < b) and finish (the count of
# failures, and the exit status: 0 only without any).
set -uo pipefail
texsim=$(realpath "$1")
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
failures=0

pass() { echo "ok   $1"; }
fail() { echo "FAIL $1"; failures=$((failures + 1)); }

column() {  # the cell of setting $1 under header $2 in the Markdown table $work/table.md
  awk -F'|' -v v="$1" -v h="$2" '
    function trim(x) { gsub(/^ +| +$/, "", x); return x }
    NR == 1 { for (i = 2; i < NF; ++i) if (trim($i) == h) c = i; next }
    c && trim($2) == v { print trim($c) }' "$work/table.md"
}
less() { awk -v a="$1" -v b="$2" 'BEGIN { exit !(a < b) }'; }

finish() {
  echo "$failures failure(s)"
  exit $((failures > 0))
}
