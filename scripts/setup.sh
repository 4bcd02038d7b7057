#!/usr/bin/env bash
# Installs the Debian 12 packages the project needs, with apt-get, when they are missing;
# does nothing when they are all present.
# TMU_SETUP=tests (scripts/test.sh sets it) leaves out the tools no test runs: clang and its
# fuzzing runtime (scripts/fuzz.sh) and gtkwave (for looking at waveforms), about a third of
# what a fresh machine downloads.
set -euo pipefail

PACKAGES=(
  cmake ninja-build g++ ccache pkg-config git       # build
  clang-format                                       # style check
  verilator libsystemc-dev                           # rtl and hls models
  iverilog                                           # the rtl under a second simulator
  libglm-dev libopenimageio-dev openimageio-tools    # ideal models, image I/O, idiff
  libcli11-dev nlohmann-json3-dev libfmt-dev         # texsim
  libgtest-dev libbenchmark-dev                      # tests, benchmarks
  libocct-modeling-data-dev libtbb-dev               # NURBS test reference (OCCT links libtbb.so)
  yosys berkeley-abc                                 # synthesis check, cell counts
  python3 python3-matplotlib python3-numpy           # plots
  python3-scipy                                      # the volume unit's independent reference
  slurm-wlm munge                                    # texsim regress --slurm and its test
)
if [[ ${TMU_SETUP:-all} != tests ]]; then
  PACKAGES+=(
    clang libclang-rt-14-dev                         # libFuzzer targets (scripts/fuzz.sh)
    gtkwave                                          # viewing mismatch waveforms
  )
fi

missing=()
for p in "${PACKAGES[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if ((${#missing[@]} == 0)); then
  echo "setup: all ${#PACKAGES[@]} packages present"
  exit 0
fi

echo "setup: installing ${missing[*]}"
sudo=""
if [[ $(id -u) -ne 0 ]]; then sudo=sudo; fi
$sudo apt-get update -q
DEBIAN_FRONTEND=noninteractive $sudo apt-get install -y -q --no-install-recommends "${missing[@]}"
