#!/usr/bin/env bash
# Builds everything with clang (the `fuzz` preset), the libFuzzer targets
# included, and runs each target for a bounded time on its seed corpus:
# scripts/fuzz.sh [seconds per target] [seconds per lesson's command line]
# (default 60, and the first number). New inputs go to
# build-fuzz/corpus/, never into the committed seeds. Any crash, leak,
# sanitizer report or unexpected exception fails the run and leaves the input
# as build-fuzz/findings/<target>/crash-*; make it a regression test and a
# seed. See tests/fuzz/CMakeLists.txt.
# The random seed is fixed (FUZZ_SEED, default 1) so that a CI run can be
# repeated exactly; set FUZZ_SEED=0 for a fresh one each run.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
cli_seconds="${2:-$seconds}"
seed="${FUZZ_SEED:-1}"

scripts/setup.sh fuzz
cmake --preset fuzz
cmake --build --preset fuzz

run_target() {  # run_target <seconds> <binary> <seed folder> <max input bytes> [libFuzzer options...]
    local seconds="$1" target="$2" seeds="$3" max_len="$4"
    shift 4
    local name
    name="$(basename "$target")"
    mkdir -p "build-fuzz/corpus/$name" "build-fuzz/findings/$name"
    echo "fuzz: $name for ${seconds}s"
    if ! "$target" "build-fuzz/corpus/$name" "$seeds" -max_total_time="$seconds" \
        -max_len="$max_len" -timeout=20 -rss_limit_mb=4096 -print_final_stats=1 -seed="$seed" \
        -artifact_prefix="build-fuzz/findings/$name/" "$@" >"build-fuzz/$name.log" 2>&1; then
        tail -n 60 "build-fuzz/$name.log"
        echo "fuzz: $name FOUND A PROBLEM; input in build-fuzz/findings/$name/"
        return 1
    fi
    grep -E "stat::number_of_executed_units|stat::new_units_added" "build-fuzz/$name.log" |
        tr '\n' ' ' | sed "s/^/fuzz: $name: /"
    echo
}

# The targets run two at a time (libFuzzer runs on one core; this machine
# has two), each for the full time: FUZZ_JOBS sets how many at once.
jobs_at_once="${FUZZ_JOBS:-2}"
status=0
running=0
start() {  # start <run_target arguments...>: in the background, at most jobs_at_once
    run_target "$@" &
    running=$((running + 1))
    if [ "$running" -ge "$jobs_at_once" ]; then
        wait -n || status=1
        running=$((running - 1))
    fi
}
start "$seconds" build-fuzz/tests/fuzz/fuzz_tga tests/fuzz/corpus/tga 65536
start "$seconds" build-fuzz/tests/fuzz/fuzz_obj tests/fuzz/corpus/obj 16384
start "$seconds" build-fuzz/tests/fuzz/fuzz_texture tests/fuzz/corpus/texture 65536
start "$seconds" build-fuzz/tests/fuzz/fuzz_clipper tests/fuzz/corpus/clipper 48
for cli in build-fuzz/tests/fuzz/fuzz_cli_*; do
    # The lessons print a line per run and an error per refused option: keep
    # stdout closed (-close_fd_mask=1); libFuzzer's own report goes to stderr.
    start "$cli_seconds" "$cli" tests/fuzz/corpus/cli 512 -close_fd_mask=1
done
while [ "$running" -gt 0 ]; do
    wait -n || status=1
    running=$((running - 1))
done
if [ "$status" -ne 0 ]; then
    echo "fuzz: findings above"
    exit 1
fi
echo "fuzz: no findings"
