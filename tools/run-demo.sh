#!/usr/bin/env bash
# Builds the tumble program (Release) and runs the friction demo of handout part 3, task 4.
# Extra arguments go to `tumble run`, e.g. --csv out.csv or --set rb.elasticity=0.7.
set -euo pipefail
cd "$(dirname "$0")/.."

# only the packages of the tumble program: no viewer, tests, benchmarks, peer engines or MPI
bash tools/install-deps.sh --cli
cmake -S . -B build -G Ninja -DCMAKE_BUILD_TYPE=Release -DTUMBLE_BUILD_VIEWER=OFF \
    -DTUMBLE_BUILD_TESTS=OFF -DTUMBLE_BUILD_BENCH=OFF -DTUMBLE_BUILD_PEERS=OFF \
    -DTUMBLE_BUILD_MPI=OFF
cmake --build build --target tumble_cli
exec build/apps/cli/tumble run scenarios/part3_task4_friction.toml "$@"
