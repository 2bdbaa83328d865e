#!/usr/bin/env bash
# Builds Box3D as a static library for tumble's optional Box3D peer
# (bench/peers/box3d_peer.cpp). Downloads nothing: pass the path of a Box3D
# checkout (its CMakeLists.txt, src/ and include/ are all that is read). The
# build goes outside the repository, so no Box3D code or object ever lands in
# tumble's tree.
#
#   tools/build-box3d-peer.sh ../box3d [build-dir]   (build-dir: ../box3d-build beside the checkout)
#
# Release (-O3 -DNDEBUG) builds only the box3d library target: no samples, unit
# tests, benchmarks or docs, no Tracy profiling; Box3D's validation works only
# without NDEBUG, so it is off as well. SIMD is Box3D's default for x86-64,
# SSE2 (BOX3D_DISABLE_SIMD off; Box3D has no AVX option), and single precision
# (BOX3D_DOUBLE_PRECISION off), which the peer's headers assume: that option
# changes the ABI of b3Pos, so change both together.
set -euo pipefail

if [[ $# -lt 1 ]]; then
    echo "usage: $0 <box3d-source-dir> [build-dir]" >&2
    exit 2
fi
src=$(cd "$1" && pwd)
build=${2:-$(dirname "$src")/box3d-build}
[[ -f "$src/include/box3d/box3d.h" && -f "$src/src/CMakeLists.txt" ]] ||
    { echo "$src has no include/box3d/box3d.h or src/CMakeLists.txt" >&2; exit 2; }

# Box3D's project enables C++ too (for its samples), so both compilers are named.
cmake -S "$src" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release \
    -DCMAKE_C_COMPILER="${CC:-gcc}" \
    -DCMAKE_CXX_COMPILER="${CXX:-g++}" \
    -DCMAKE_POSITION_INDEPENDENT_CODE=ON \
    -DBUILD_SHARED_LIBS=OFF \
    -DBOX3D_DISABLE_SIMD=OFF \
    -DBOX3D_DOUBLE_PRECISION=OFF \
    -DBOX3D_PROFILE=OFF -DBOX3D_VALIDATE=OFF -DBOX3D_SANITIZE=OFF \
    -DBOX3D_SAMPLES=OFF -DBOX3D_UNIT_TESTS=OFF -DBOX3D_BENCHMARKS=OFF -DBOX3D_DOCS=OFF

nice -n 10 cmake --build "$build" --target box3d -j "${JOBS:-2}"

lib=$(find "$build" -name 'libbox3d.a' -print -quit)
[[ -n "$lib" ]] || { echo "no libbox3d.a under $build" >&2; exit 1; }
echo "built $lib from $src ($(git -C "$src" rev-parse --short=8 HEAD 2>/dev/null || echo 'unknown commit'))"
