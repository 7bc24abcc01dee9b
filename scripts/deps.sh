#!/usr/bin/env bash
# Installs the Debian packages one make target needs, only those missing (quick when all are present).
#   scripts/deps.sh [build|test|demo|bench|fuzz ...]     (no argument: build)
# Every package is named: apt runs with --no-install-recommends, so nothing arrives as a recommendation.
set -euo pipefail

# The host build and the ARM7TDMI cross-build (make host, firmware, size).
BUILD_PKGS=(build-essential cmake ninja-build pkg-config
            libcli11-dev libpng-dev libyaml-cpp-dev nlohmann-json3-dev libeigen3-dev
            libunicorn-dev libbluetooth-dev
            gcc-arm-none-eabi binutils-arm-none-eabi libnewlib-arm-none-eabi
            libstdc++-arm-none-eabi-newlib)   # libstdc++_nano for the emulator's probe firmwares
# make test: GoogleTest; gnuplot for the plot tests; LEGO's firmware image and libnxt's fwflash for flash.
TEST_PKGS=(libgtest-dev libgmock-dev gnuplot-nox nxt-firmware libnxt)
# make demo: the build alone.
DEMO_PKGS=()
# make bench: the PathFinding.js peer (npm, installed into build/peer by the bench itself).
BENCH_PKGS=(nodejs npm gnuplot-nox)
# make fuzz: clang's libFuzzer.
FUZZ_PKGS=(clang libclang-rt-14-dev)
# make format: the formatter the tree's style (.clang-format) is written for.
FORMAT_PKGS=(clang-format)

want=("${BUILD_PKGS[@]}")
for target in "${@:-build}"; do
  case "$target" in
    build) ;;
    test)  want+=("${TEST_PKGS[@]}") ;;
    demo)  want+=(${DEMO_PKGS[@]+"${DEMO_PKGS[@]}"}) ;;
    bench) want+=("${BENCH_PKGS[@]}") ;;
    fuzz)  want+=("${FUZZ_PKGS[@]}") ;;
    format) want+=("${FORMAT_PKGS[@]}") ;;
    *) echo "deps: unknown target '$target' (build, test, demo, bench, fuzz, format)" >&2; exit 2 ;;
  esac
done

missing=()
for p in "${want[@]}"; do
  case "$p" in  # a machine may carry its own Node.js outside Debian's packages
    nodejs) command -v node >/dev/null && continue ;;
    npm)    command -v npm  >/dev/null && continue ;;
  esac
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q 'install ok installed' && continue
  [[ " ${missing[*]-} " == *" $p "* ]] || missing+=("$p")
done
[ ${#missing[@]} -eq 0 ] && exit 0

echo "deps: installing ${missing[*]}"
SUDO=""
if [ "$(id -u)" -ne 0 ]; then
  command -v sudo >/dev/null || { echo "deps: need root or sudo to install: ${missing[*]}" >&2; exit 1; }
  SUDO=sudo
fi
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
