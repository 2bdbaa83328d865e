#!/usr/bin/env bash
# Builds everything with AddressSanitizer and UndefinedBehaviorSanitizer (Debug, build-asan/) and
# runs the whole test suite; any sanitizer report fails (issue 6, docs/robustness.md).
set -euo pipefail
cd "$(dirname "$0")/.."

bash tools/install-deps.sh
# The viewer needs a display and its own libraries; it is not what the sanitizers are for here.
# MPI is left out too: Open MPI keeps allocations to the end of the process, which
# LeakSanitizer would report against the mpirun test of tumble throw. The peer engines of
# tumble bench are other projects' code, built and run by tools/run-tests.sh.
cmake -S . -B build-asan -G Ninja -DCMAKE_BUILD_TYPE=Debug -DTUMBLE_SANITIZE=ON \
    -DTUMBLE_WARNINGS_AS_ERRORS=ON -DTUMBLE_BUILD_VIEWER=OFF -DTUMBLE_BUILD_MPI=OFF \
    -DTUMBLE_BUILD_PEERS=OFF
cmake --build build-asan
# halt_on_error: a UBSan report aborts the test (by default UBSan only prints and goes on).
export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1:strict_string_checks=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"
# The long runs are ~20x slower under the sanitizers: 10^5 steps instead of 10^6.
export TUMBLE_LONG_RUN_STEPS="${TUMBLE_LONG_RUN_STEPS:-100000}"
# consumer.find_package is left out: it links the installed (instrumented) static library into a
# plain project, which cannot work without the sanitizer runtime; it is a packaging test, run by
# tools/run-tests.sh.
ctest --test-dir build-asan --output-on-failure -j2 --timeout 900 -E '^consumer\.find_package$'

