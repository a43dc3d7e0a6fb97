#!/usr/bin/env bash
# Runs every libFuzzer target of a GS_FUZZ build (cmake --preset fuzz) for a bounded time, each on a scratch
# copy of its seed corpus (the checked-in corpus stays as it is). Fails if any fuzzer finds a crash, sanitizer
# report, leak, timeout or out-of-memory input, and prints where the reproducer was written.
#
# Usage: tests/fuzz/run.sh BUILD_DIR [SECONDS_PER_TARGET=60] [WORK_DIR=BUILD_DIR/fuzz-run] [TARGET...]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
build=$(cd "${1:?usage: $0 BUILD_DIR [SECONDS_PER_TARGET] [WORK_DIR] [TARGET...]}" && pwd)
seconds=${2:-60}
work=${3:-$build/fuzz-run}
shift $(($# < 3 ? $# : 3))
targets=("$@")
((${#targets[@]})) || targets=(gltf cage settings)

# Leaks count as findings; only third-party leaks listed in lsan.supp are ignored.
export LSAN_OPTIONS="suppressions=$here/lsan.supp:print_suppressions=0"
rm -rf "$work"
status=0
for target in "${targets[@]}"; do
    dir="$work/$target"
    mkdir -p "$dir/corpus"
    cp "$here/corpus/$target"/* "$dir/corpus/"
    echo "fuzz: gs-fuzz-$target for ${seconds}s"
    # -timeout: one input running longer is a hang; -rss_limit_mb also caps any single allocation.
    if "$build/bin/gs-fuzz-$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
        -dict="$here/$target.dict" -artifact_prefix="$dir/" -print_final_stats=1 "$dir/corpus" \
        >"$dir/log" 2>&1; then
        grep -E "^stat::number_of_executed_units|^#[0-9]+[[:space:]]+DONE" "$dir/log" | sed "s/^/fuzz:   /"
    else
        status=1
        echo "fuzz: gs-fuzz-$target FOUND A PROBLEM (full log: $dir/log); last lines:"
        tail -n 40 "$dir/log"
        for artifact in "$dir"/crash-* "$dir"/leak-* "$dir"/timeout-* "$dir"/oom-*; do
            [[ -e $artifact ]] || continue
            echo "fuzz: reproduce with $build/bin/gs-fuzz-$target $artifact"
            echo "fuzz: once fixed, add it to tests/fuzz/corpus/$target/ so every CI run replays it"
        done
    fi
done
exit $status
