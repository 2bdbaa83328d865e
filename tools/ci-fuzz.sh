#!/usr/bin/env bash
# Builds the libFuzzer targets with clang, AddressSanitizer and UndefinedBehaviorSanitizer
# (build-fuzz/) and runs each for FUZZ_SECONDS (default 120) from its seeds and regressions. Any
# crash, hang, leak or sanitizer report fails, and the input is left in build-fuzz/findings/;
# copy it to tests/fuzz/regressions/<target>/ with the fix. Longer by hand: FUZZ_SECONDS=3600.
set -euo pipefail
cd "$(dirname "$0")/.."

FUZZ_SECONDS="${FUZZ_SECONDS:-120}"
# Targets whose findings are printed in full but do not fail the run, while an open finding of
# theirs is being fixed (named in .ci/run with the issue); empty: every finding fails.
FUZZ_REPORT_ONLY="${FUZZ_REPORT_ONLY:-}"

bash tools/install-deps.sh
CXX="${FUZZ_CXX:-clang++}"
cmake -S . -B build-fuzz -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER="$CXX" \
    -DTUMBLE_BUILD_FUZZ=ON -DTUMBLE_SANITIZE=ON -DTUMBLE_BUILD_VIEWER=OFF -DTUMBLE_BUILD_CLI=OFF
cmake --build build-fuzz --target scenario_loader_fuzzer world_step_fuzzer

export ASAN_OPTIONS="detect_leaks=1:abort_on_error=1:halt_on_error=1"
export UBSAN_OPTIONS="halt_on_error=1:abort_on_error=1:print_stacktrace=1"

findings=build-fuzz/findings
# Findings of an earlier run are not this run's: start empty (they were reported then).
rm -rf "$findings"
mkdir -p "$findings"
status=0
run_fuzzer() {
    local target="$1"
    local unit_seconds="$2"
    shift 2
    local corpus="build-fuzz/corpus/$target"
    local log="build-fuzz/${target}.log"
    mkdir -p "$corpus"
    # git keeps no empty folder: a target with no regression yet has none in a fresh clone
    mkdir -p "tests/fuzz/regressions/$target"
    echo "ci-fuzz: $target for ${FUZZ_SECONDS} s"
    # -timeout: one input running longer than unit_seconds is a hang, and one running longer than
    # that is reported as a slow unit, a finding too; -rss_limit_mb: a memory blow-up.
    # The first corpus directory collects new inputs; the others are read only.
    local rc=0
    # A target whose findings are reported only keeps fuzzing after one (in a child process) so
    # the whole FUZZ_SECONDS is spent searching.
    local keep_going=()
    if [[ " $FUZZ_REPORT_ONLY " == *" $target "* ]]; then
        keep_going=(-fork=1 -ignore_crashes=1)
    fi
    "build-fuzz/tests/fuzz/${target}_fuzzer" "${keep_going[@]}" "$corpus" "$@" "tests/fuzz/regressions/$target" \
        -max_total_time="$FUZZ_SECONDS" -timeout="$unit_seconds" -report_slow_units="$unit_seconds" -rss_limit_mb=2048 \
        -artifact_prefix="$findings/${target}-" -print_final_stats=1 >"$log" 2>&1 || rc=$?
    grep -E "^#[0-9]+ +(INITED|DONE)|^stat::(number_of_executed_units|average_exec_per_sec|new_units_added|peak_rss_mb)|^Done" "$log" || true
    if [[ $rc -ne 0 ]] || compgen -G "$findings/${target}-*" >/dev/null; then
        tail -n 60 "$log" >&2
        if [[ " $FUZZ_REPORT_ONLY " == *" $target "* ]]; then
            echo "ci-fuzz: $target FINDING, reported only (FUZZ_REPORT_ONLY); inputs in $findings" >&2
        else
            # a slow unit (-report_slow_units) exits 0 but leaves its input
            echo "ci-fuzz: $target FAILED (exit $rc): $(cd "$findings" && ls -m "${target}"-* 2>/dev/null); inputs in $findings, log $log" >&2
            status=1
        fi
    else
        echo "ci-fuzz: $target: no findings"
    fi
}

# A scenario input steps for at most 2 s (tests/fuzz/scenario_loader_fuzzer.cpp) and then
# finishes the step under way: the slowest steps found (an elastic stack of 20 dropped) take 0.1 s
# in a release build and about 5 s under the sanitizers. 30 s leaves room for a loaded machine; a
# step that never ends still runs past it.
run_fuzzer scenario_loader 30 scenarios -dict=tests/fuzz/scenario.dict -max_len=4096
# A world-step input is up to 300 steps of one body, each bounded by (4.3b) (32 sub-steps, 128
# searches and their resting solves, 512 advances, docs/physics/04-detection.md), not by a time:
# the slowest inputs found take about 1 s a run in a release build and up to 20 s under the
# sanitizers on a loaded 2-core machine. 60 s is three times that; a loop that never ends still
# runs past it.
run_fuzzer world_step 60 tests/fuzz/seeds/world_step -max_len=256
exit "$status"
