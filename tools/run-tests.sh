#!/usr/bin/env bash
# Builds everything with warnings as errors and runs the whole test suite.
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/install-deps.sh
# every part on, also when run-demo.sh left some off in build/'s cache
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUMBLE_WARNINGS_AS_ERRORS=ON \
    -DTUMBLE_BUILD_VIEWER=ON -DTUMBLE_BUILD_TESTS=ON -DTUMBLE_BUILD_BENCH=ON \
    -DTUMBLE_BUILD_PEERS=ON -DTUMBLE_BUILD_MPI=ON
cmake --build build
ctest --test-dir build --output-on-failure -j2
