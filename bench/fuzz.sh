#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs every libFuzzer harness of tests/fuzz for SECONDS each (or until each has run N inputs), one
# after the other, and prints a table of executions, coverage and findings.
#
#   bench/fuzz.sh [--seeds-only] SECONDS [HARNESS...]
#   bench/fuzz.sh [--seeds-only] --runs N [HARNESS...]
#
# Builds what it needs with the `fuzz` preset (clang, ASan + UBSan) in build-fuzz/. Each harness
# starts from its seeds (tests' data and tests/data/fuzz/<harness>/, listed by CMake in
# <harness>.seeds, with the corpus kept in tests/fuzz/corpus/<harness>/) and the corpus earlier runs
# grew in build-fuzz/fuzz/corpus/<harness>/ (see tests/fuzz/runharness.sh). Findings are written to
# build-fuzz/fuzz/artifacts/<harness>/ (crash-*, leak-*, timeout-*, oom-*) and printed in base64; the
# log of each run is build-fuzz/fuzz/<harness>.log. Exits non-zero when anything was found.
# With --seeds-only each harness starts from its seeds alone, in build-fuzz/fuzz/seeds-only/<harness>/
# (emptied first), so a run shows what a fresh start finds; the grown corpora stay as they are.
# An input taking over 1 s is a timeout; FUZZ_TIMEOUT=S sets another limit (for long runs on a machine
# that is not quiet, where a starved harness can take that long over an input it replays in milliseconds).
set -eu

usage="usage: $0 [--seeds-only] SECONDS [HARNESS...] | $0 [--seeds-only] --runs N [HARNESS...]"
fresh= corpus_folder=corpus
if [ "${1:-}" = --seeds-only ]; then
    fresh=--fresh corpus_folder=seeds-only
    shift
fi
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
status=0
for harness in "$@"; do
    nice -n 10 "$source_dir/tests/fuzz/runharness.sh" $fresh "$harness_dir/$harness" "$limit" \
        "$work_dir/$corpus_folder/$harness" "$work_dir/artifacts/$harness" "$work_dir/$harness.log" \
        "$harness_dir/$harness.seeds" >>"$table" || status=1
done

printf '%-20s %12s %8s %8s %8s %8s %8s %8s\n' harness executions seconds coverage features crashes timeouts \
    leaks
cat "$table"
exit $status
