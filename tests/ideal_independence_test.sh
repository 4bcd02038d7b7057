#!/usr/bin/env bash
# The ideal models share no arithmetic with golden (issue 16 item 1): every
# golden/*/*_ideal.{hpp,cpp} includes only standard headers, <glm/...>, ideal headers
# (*_ideal.hpp) and the definitions-only headers listed below, and those headers include only
# standard headers and each other, so that nothing reaches golden's arithmetic through them;
# and each of those headers is listed (by its path under golden/) in a document under docs/.
# Prints each violation as `FILE:LINE includes HEADER (not a definition header)` and exits 1
# if there is any. Usage: tests/ideal_independence_test.sh
set -uo pipefail
root=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
cd "$root/golden" || exit 1

# Ideal models being made independent (issue 16 item 1): their violations are printed but do
# not fail the check. A file listed here that no longer violates fails it: take it out.
pending=()

# The definitions-only headers (constants, data, containers; no arithmetic), paths under
# golden/ as the includes spell them, each with what it defines:
definitions=(
  formats/formats.def                 # the interface table itself: rows of data for macros
  formats/constants.hpp               # formats.def's shared constants (the hash's rows)
  perlin/noise_definition.hpp         # the noise lattice's widths and the hash's xor rows
  perlin/material_definition.hpp      # the material registers and colour tables
  deflect/sphere_grid_definition.hpp  # the angle grid's sizes and step, the angles' fields
  deflect/view_frame_definition.hpp   # the view frame's three vectors
  texram/level8.hpp                   # the mipmap level container (8-bit texels)
  texram/source_texels.hpp            # what a texture was made from: planes, CLUT, flags
  texram/sampler_config.hpp           # the sampler's enums and registers, RGBA8888 packing
  texram/detail_definition.hpp        # the detail map's combine rules and shape (16 x 16 regions, 4 levels)
  footprint/q_rule.hpp                # which measure of the footprint's width q
  tau/tau_definition.hpp              # the tau grid's shape, the interpolations' names, the extrapolation rule
  volume/voxels.hpp                   # the volume data set container (8-bit voxels, x fastest)
)

listed() {  # is $1 one of the remaining arguments
  local x=$1 y
  shift
  for y in "$@"; do [[ $x == "$y" ]] && return 0; done
  return 1
}

# The includes of file $1 not allowed there, one `FILE:LINE includes HEADER` each; $2 is
# "ideal" (ideal headers and <glm/...> allowed too) or "definition".
violations() {
  local file=$1 kind=$2 line text header
  while IFS=: read -r line text; do
    # The spelling as written: <name> or "name".
    header=$(sed -E 's/^[[:space:]]*#[[:space:]]*include[[:space:]]*([<"][^>"]*[>"]).*/\1/' <<<"$text")
    if [[ $header =~ ^\<[a-z_]+\>$ ]]; then continue; fi  # a standard header: <cmath>
    header=${header:1:-1}
    if listed "$header" "${definitions[@]}"; then continue; fi
    if [[ $kind == ideal && ($header == glm/* || $header == *_ideal.hpp) ]]; then continue; fi
    echo "golden/$file:$line includes $header (not a definition header)"
  done < <(grep -nE '^[[:space:]]*#[[:space:]]*include' "$file")
}

failures=0
shopt -s nullglob
ideals=(*/*_ideal.hpp */*_ideal.cpp)
if ((${#ideals[@]} == 0)); then
  echo "no golden/*/*_ideal.{hpp,cpp} found under $root"
  exit 1
fi
for f in "${ideals[@]}"; do
  found=$(violations "$f" ideal)
  if listed "$f" "${pending[@]}"; then
    if [[ -z $found ]]; then
      echo "golden/$f: independent now, take it out of pending"
      failures=$((failures + 1))
    else
      sed 's/^/pending: /' <<<"$found"
    fi
  elif [[ -n $found ]]; then
    echo "$found"
    failures=$((failures + $(wc -l <<<"$found")))
  fi
done
for f in "${definitions[@]}"; do
  if [[ ! -f $f ]]; then
    echo "golden/$f: listed as a definition header, but there is no such file"
    failures=$((failures + 1))
    continue
  fi
  found=$(violations "$f" definition)
  [[ -n $found ]] && echo "$found" && failures=$((failures + $(wc -l <<<"$found")))
  # A shared definition is written down where its block is described, with its test.
  if ! grep -q "$f" "$root"/docs/*.md; then
    echo "golden/$f: a definition header no document under docs/ lists"
    failures=$((failures + 1))
  fi
done
for f in "${pending[@]}"; do
  [[ -f $f ]] || { echo "golden/$f: pending, but there is no such file" && failures=$((failures + 1)); }
done

echo "${#ideals[@]} ideal files, ${#definitions[@]} definition headers, ${#pending[@]} pending:" \
  "$failures violation(s)"
exit $((failures > 0))
