#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every libFuzzer harness of tests/fuzz for SECONDS each (or until each has run N inputs), one
# after the other, and prints a table of executions, coverage and findings.
#
#   bench/fuzz.sh SECONDS [HARNESS...]
#   bench/fuzz.sh --runs N [HARNESS...]
#
# Builds what it needs with the `fuzz` preset (clang, ASan + UBSan) in build-fuzz/. Each harness
# starts from its seeds (tests' data and tests/data/fuzz/<harness>/, listed by CMake in
# <harness>.seeds) plus the corpus earlier runs grew in build-fuzz/fuzz/corpus/<harness>/.
# Inputs are at most 4 KiB (larger seeds are cut there); one taking more than 1 s is a timeout.
# Findings are written to build-fuzz/fuzz/artifacts/<harness>/ (crash-*, leak-*, timeout-*, oom-*);
# the log of each run is build-fuzz/fuzz/<harness>.log. Exits non-zero when anything was found.
set -eu

usage="usage: $0 SECONDS [HARNESS...] | $0 --runs N [HARNESS...]"
if [ $# -lt 1 ]; then
    echo "$usage" >&2
    exit 2
fi
if [ "$1" = --runs ]; then
    [ $# -ge 2 ] || { echo "$usage" >&2; exit 2; }
    limit="-runs=$2"
    shift 2
else
    limit="-max_total_time=$1"
    shift
fi

source_dir=$(cd "$(dirname "$0")/.." && pwd)
build_dir="$source_dir/build-fuzz"
work_dir="$build_dir/fuzz"
harness_dir="$build_dir/tests/fuzz"

cd "$source_dir"
if [ ! -f "$build_dir/CMakeCache.txt" ]; then
    cmake --preset fuzz >/dev/null
fi
if ! nice -n 10 cmake --build --preset fuzz >"$build_dir/fuzz-build.log" 2>&1; then
    tail -n 30 "$build_dir/fuzz-build.log" >&2
    exit 1
fi

if [ $# -eq 0 ]; then
    set -- $(cd "$harness_dir" && ls -- *.seeds | sed 's/\.seeds$//')
fi

# Third-party allocations kept until exit (Qt, omniORB); reviewed, see the file.
export LSAN_OPTIONS="suppressions=$source_dir/tests/fuzz/lsan.supp:print_suppressions=0"
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:detect_leaks=1"
export UBSAN_OPTIONS="print_stacktrace=1:halt_on_error=1"

table="$work_dir/table.txt"
mkdir -p "$work_dir"
: >"$table"
total_runs=0 total_execs=0 total_crashes=0 total_leaks=0 total_timeouts=0
for harness in "$@"; do
    corpus="$work_dir/corpus/$harness"
    artifacts="$work_dir/artifacts/$harness"
    log="$work_dir/$harness.log"
    mkdir -p "$corpus" "$artifacts"
    rm -f "$artifacts"/*
    # Seeds under their content's hash, as libFuzzer names corpus files.
    while IFS= read -r seed; do
        [ -f "$seed" ] || continue
        cp "$seed" "$corpus/$(sha1sum "$seed" | cut -c1-40)"
    done <"$harness_dir/$harness.seeds"

    nice -n 10 "$harness_dir/$harness" "$limit" -timeout=1 -rss_limit_mb=2048 -max_len=4096 \
        -print_final_stats=1 -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1 || true

    execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
    execs=${execs:-0}
    coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    features=$(grep -o 'ft: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
    crashes=$(find "$artifacts" -name 'crash-*' -o -name 'oom-*' | wc -l)
    leaks=$(find "$artifacts" -name 'leak-*' | wc -l)
    timeouts=$(find "$artifacts" -name 'timeout-*' | wc -l)
    seconds_taken=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n 1)
    printf '%-20s %12s %8s %8s %8s %8s %8s %8s\n' "$harness" "$execs" "${seconds_taken:-?}" \
        "${coverage:-?}" "${features:-?}" "$crashes" "$timeouts" "$leaks" >>"$table"

    total_runs=$((total_runs + 1))
    total_execs=$((total_execs + execs))
    total_crashes=$((total_crashes + crashes))
    total_leaks=$((total_leaks + leaks))
    total_timeouts=$((total_timeouts + timeouts))
done

printf '%-20s %12s %8s %8s %8s %8s %8s %8s\n' harness executions seconds coverage features crashes timeouts \
    leaks
cat "$table"
echo "$total_runs harnesses, $total_execs executions, $total_crashes crashes, $total_leaks leaks," \
    "$total_timeouts timeouts"
[ $((total_crashes + total_leaks + total_timeouts)) -eq 0 ]
