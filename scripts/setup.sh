#!/usr/bin/env bash
# One-step set-up on a fresh Debian 12 machine: install the packages, build, run the default scenario.
set -euo pipefail
cd "$(dirname "$0")/.."

PACKAGES=(
  build-essential cmake ninja-build pkg-config
  libsystemc-dev libtomlplusplus-dev libcli11-dev nlohmann-json3-dev
  libgtest-dev libgmock-dev
  libeigen3-dev libboost-dev libfmt-dev libdxflib-dev
  python3 sigrok-cli
  slurm-wlm munge
  gnuplot-nox libxml2-utils python3-pil
  clang libclang-rt-14-dev llvm
  gcc-avr binutils-avr avr-libc simavr libsimavr-dev libelf-dev
  iverilog yosys nextpnr-ice40 verilator
)
SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi
$SUDO apt-get update -qq
DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -qq --no-install-recommends "${PACKAGES[@]}" >/dev/null

cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release
# cncsim alone, with the AVR firmwares it loads at run time (its build dependencies): the README's test command
# builds the test suite into the same folder.
cmake --build build -j2 --target cncsim
mkdir -p out
./build/sim/cncsim run scenarios/fpga-uart/square_20mm.toml --vcd out/square.vcd --report out/square.json
