#!/usr/bin/env bash
# Builds Jolt Physics as a static library for tumble's optional Jolt peer
# (bench/peers/jolt_peer.cpp). Downloads nothing: pass the path of a Jolt
# checkout (its Jolt/ and Build/ folders are all that is read). The build goes
# outside the repository, so no Jolt code or object ever lands in tumble's tree.
#
#   tools/build-jolt-peer.sh ../JoltPhysics [build-dir]   (build-dir: ../jolt-build beside the checkout)
#
# Distribution is Jolt's Release (-O3) without its profiler, debug renderer and
# floating-point exception checks, the configuration Jolt times itself in.
# The SIMD options are Jolt's x86-64 defaults (AVX2, FMA, F16C, LZCNT, TZCNT);
# tumble's CMake passes the matching JPH_* definitions to the peer
# (TUMBLE_JOLT_DEFINITIONS), so change both together.
set -euo pipefail

if [[ $# -lt 1 ]]; then
    echo "usage: $0 <jolt-source-dir> [build-dir]" >&2
    exit 2
fi
src=$(cd "$1" && pwd)
build=${2:-$(dirname "$src")/jolt-build}
[[ -f "$src/Build/CMakeLists.txt" ]] || { echo "$src has no Build/CMakeLists.txt" >&2; exit 2; }

# GPU compute back ends are off: the peer uses only rigid bodies on the CPU.
cmake -S "$src/Build" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Distribution \
    -DCMAKE_CXX_COMPILER="${CXX:-g++}" \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DINTERPROCEDURAL_OPTIMIZATION=OFF \
    -DDOUBLE_PRECISION=OFF \
    -DUSE_AVX2=ON \
    -DTARGET_UNIT_TESTS=OFF -DTARGET_HELLO_WORLD=OFF -DTARGET_PERFORMANCE_TEST=OFF \
    -DTARGET_SAMPLES=OFF -DTARGET_VIEWER=OFF \
    -DJPH_USE_VK=OFF -DJPH_USE_DX12=OFF -DJPH_USE_MTL=OFF -DJPH_USE_CPU_COMPUTE=OFF \
    -DENABLE_INSTALL=OFF

nice -n 10 cmake --build "$build" --target Jolt -j "${JOBS:-2}"

echo "built $build/libJolt.a from $src ($(git -C "$src" rev-parse --short=8 HEAD 2>/dev/null || echo 'unknown commit'))"
