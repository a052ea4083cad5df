#!/bin/sh
# SPDX-License-Identifier: MIT
# Runs one libFuzzer harness and prints its row of the fuzz table:
#   harness executions seconds coverage features crashes timeouts leaks
#
#   tests/fuzz/runharness.sh [--fresh] [--row FILE] HARNESS LIMIT WORK_CORPUS ARTIFACTS LOG SEEDS_FILE
#
# LIMIT is libFuzzer's -max_total_time=S or -runs=N. The files SEEDS_FILE lists (one path a line: the
# seeds, regression inputs and kept corpus CMake found for the harness) are copied into WORK_CORPUS
# under their content's hash, as libFuzzer names corpus files, and the harness runs on WORK_CORPUS
# (which it grows). Inputs are at most 4 KiB; one taking more than 1 s is a timeout (FUZZ_TIMEOUT=S
# in the environment: S seconds, for long runs beside other work, where a starved process can take a
# second over a 5 ms input). Findings go to ARTIFACTS (emptied first) and are printed in base64 after
# the row; the exit status is 1 when there are any. With --fresh, WORK_CORPUS is emptied first, so
# that the run starts from the seeds and the corpus directories alone; with --row FILE, the row is
# written to FILE as well.
set -eu

fresh=0 row_file=
while [ $# -gt 0 ]; do
    case $1 in
    --fresh) fresh=1 ;;
    --row) row_file=$2; shift ;;
    *) break ;;
    esac
    shift
done

if [ $# -ne 6 ]; then
    echo "usage: $0 [--fresh] [--row FILE] HARNESS LIMIT WORK_CORPUS ARTIFACTS LOG SEEDS_FILE" >&2
    exit 2
fi
harness=$1 limit=$2 corpus=$3 artifacts=$4 log=$5 seeds=$6
name=$(basename "$harness")

[ "$fresh" -eq 0 ] || rm -rf "$corpus"
mkdir -p "$corpus" "$artifacts"
rm -f "$artifacts"/*
add_seed() {
    [ -f "$1" ] && cp "$1" "$corpus/$(sha1sum "$1" | cut -c1-40)"
    return 0
}
while IFS= read -r seed; do
    add_seed "$seed"
done <"$seeds"

# Once a harness has used half its RSS limit, libFuzzer hands freed memory back to the system every
# second; in a virtual machine each hand-back flushes the TLB of every CPU, and the profile harnesses
# (ASan's 256 MiB quarantine of freed memory, then their corpus, pass 1 GiB) fell from 700 to 100
# inputs a second. A quarantine of 16 MiB, far more than one input frees, keeps them well below.
export ASAN_OPTIONS="${ASAN_OPTIONS:-}:quarantine_size_mb=16"
"$harness" "$limit" -timeout="${FUZZ_TIMEOUT:-1}" -rss_limit_mb=2048 -max_len=4096 -print_final_stats=1 \
    -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1 || true

execs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log" | tail -n 1)
coverage=$(grep -o 'cov: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
features=$(grep -o 'ft: [0-9]*' "$log" | tail -n 1 | cut -d' ' -f2)
seconds=$(sed -n 's/^Done [0-9]* runs in \([0-9]*\) second.*/\1/p' "$log" | tail -n 1)
crashes=$(find "$artifacts" -name 'crash-*' -o -name 'oom-*' | wc -l)
timeouts=$(find "$artifacts" -name 'timeout-*' | wc -l)
leaks=$(find "$artifacts" -name 'leak-*' | wc -l)
row=$(printf '%-20s %12s %8s %8s %8s %8s %8s %8s' "$name" "${execs:-0}" "${seconds:-?}" "${coverage:-?}" \
    "${features:-?}" "$crashes" "$timeouts" "$leaks")
echo "$row"
[ -z "$row_file" ] || echo "$row" >"$row_file"

found=0
for finding in "$artifacts"/*; do
    [ -f "$finding" ] || continue
    found=1
    echo "$name finding $(basename "$finding") (base64): $(base64 -w0 "$finding")"
done
if [ "$found" -eq 1 ] || [ -z "${execs:-}" ]; then
    [ -n "${execs:-}" ] || echo "$name did not finish; the end of its log:"
    tail -n 40 "$log"
    exit 1
fi
