#!/usr/bin/env bash
# scripts/gen_block_descriptions.py: every bundled description generates (a header per
# description file, the binds of every top with a handshake channel), and a malformed one is
# an error naming the file and the key, with exit 1 and nothing written.
# Usage: tests/block_descriptions_test.sh scripts/gen_block_descriptions.py
source "$(dirname "${BASH_SOURCE[0]}")/check_lib.sh" "$1"
generator=$texsim  # check_lib.sh names the tool under test texsim

python3 "$generator" "$work/all" "$root"/tb/blocks/*/*.json && pass "bundled: exit 0" ||
  fail "bundled: exit $?"
headers=$(find "$work/all/blocks" -name '*_ports.hpp' | wc -l)
descriptions=$(ls "$root"/tb/blocks/*/*.json | wc -l)
[[ $headers -eq $descriptions ]] && pass "a header per description ($headers)" ||
  fail "$headers headers for $descriptions descriptions"
binds=$(cat "$work"/all/rtl/*_binds.sv | grep -c '^bind ')
# 39 when the binds were hand-written, the six readied channels of each clip-map top, the tau
# unit's three (in, node, out), the TEXRAM chip's five (drf, clut, param, mem_req, out) and the
# volume unit's three (ray, mem_req, out); the video port's two (in, out), the video rows'
# six (put, flush, hold, read, cycle, out) and the video unit's three (in, cycle, out).
[[ $binds -eq 73 ]] && pass "73 channel checks bound" || fail "$binds channel checks bound, not 73"
# Verilator reads a comment `// verilator ...` as a directive and stops on one it does not know:
# no generated comment line may start with that word (tmu_tau's binds once did).
if grep -qi '^// verilator' "$work"/all/rtl/*_binds.sv; then
  fail "a binds comment line starts with 'Verilator': $(grep -li '^// verilator' "$work"/all/rtl/*_binds.sv)"
else
  pass "no binds comment line starts with 'Verilator'"
fi

# bad NAME TEXT PATTERN: a description foo.json of TEXT fails with PATTERN in the message.
bad() {
  mkdir -p "$work/$1/foo"
  printf '%s\n' "$2" > "$work/$1/foo/foo.json"
  out=$(python3 "$generator" "$work/$1/out" "$work/$1/foo/foo.json" 2>&1)
  code=$?
  [[ $code -eq 1 && "$out" == *"foo/foo.json"*"$3"* && ! -e "$work/$1/out" ]] &&
    pass "$1: exit 1, names the file and '$3'" || fail "$1: exit $code: $out"
}
ok='"block": "foo", "summary": "s", "about": "a"'
bad kind "{$ok, \"channels\": [{\"channel\": \"in\", \"kind\": \"Sampel\"}]}" "channels[0].kind"
bad syntax "{$ok," "line 2"
bad group "{$ok, \"channels\": [{\"use\": \"nowhere\"}]}" "channels[0].use: no group 'nowhere'"
bad count "{$ok, \"channels\": [{\"channel\": \"in\", \"kind\": \"Sample\", \"fields\": {\"x\": [\"Flag\", 0]}}]}" \
  "channels[0].fields.x"
bad toplevel "[1, 2]" "(top level): must be an object"
bad name "{\"block\": \"bar\", \"summary\": \"s\", \"about\": \"a\", \"channels\": []}" "block: 'bar'"
finish
