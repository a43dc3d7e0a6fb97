#!/usr/bin/env bash
# Builds everything with warnings as errors and runs the whole test suite (GL tests on Mesa llvmpipe via EGL),
# installs the package and builds and runs examples/host-app against it (tools/package_test.sh), then the same
# suite built with AddressSanitizer + UndefinedBehaviorSanitizer, then every fuzzer for a
# bounded time on a copy of its corpus (docs/ROBUSTNESS.md). Each stage prints how long it took.
# GS_FUZZ_SECONDS: time per fuzzer, default 40.
set -euo pipefail
cd "$(dirname "$0")/.."

timings=()
stage() { # stage NAME COMMAND...: runs the command, failing the script if it fails, and records its time
    local name=$1 start=$SECONDS
    shift
    echo "== test.sh: $name"
    "$@"
    timings+=("$(printf '%-28s %4d s' "$name" $((SECONDS - start)))")
}

bash tools/setup.sh
stage "ci: configure + build" eval 'cmake --preset ci && cmake --build --preset ci'
stage "corpus (tools/corpus.sh)" env GS_CORPUS_TOOL=./build-ci/bin/gs-corpus bash tools/corpus.sh
stage "ci: tests" ctest --preset ci
stage "package: install + example host" bash tools/package_test.sh build-ci
stage "asan: configure + build" eval 'cmake --preset asan && cmake --build --preset asan'
stage "asan: tests" ctest --preset asan
stage "fuzz: configure + build" eval 'cmake --preset fuzz && cmake --build --preset fuzz'
stage "fuzz: run" tests/fuzz/run.sh build-fuzz "${GS_FUZZ_SECONDS:-40}"

echo "== test.sh: all stages passed"
printf '   %s\n' "${timings[@]}"
