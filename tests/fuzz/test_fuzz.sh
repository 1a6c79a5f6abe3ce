#!/bin/sh
# SPDX-License-Identifier: MIT
# test_fuzz.sh FUZZER REPLAY CORPUS WORKDIR RUNS - the committed regression
# corpus (under both builds) plus a bounded, reproducible smoke run.
# Prints "fuzz: N passed, N failed"; exit status 1 on any failure.
set -u
fuzzer=$1 replay=$2 corpus=$3 work=$4 runs=$5
. tests/harness/tally.sh
c2d_tally_name=fuzz
files=$(find "$corpus" -type f | sort)
nfiles=$(echo "$files" | wc -l)

# shellcheck disable=SC2086
out=$("$replay" $files)
echo "$out"
p=$(echo "$out" | sed -n 's/^fuzz-replay: \([0-9]*\) passed, \([0-9]*\) failed$/\1/p')
f=$(echo "$out" | sed -n 's/^fuzz-replay: \([0-9]*\) passed, \([0-9]*\) failed$/\2/p')
c2d_pass=$((c2d_pass + ${p:-0}))
c2d_fail=$((c2d_fail + ${f:-1}))

if "$fuzzer" -runs=0 "$corpus" >"$work/corpus.log" 2>&1; then
    c2d_passed
    echo "fuzz: libFuzzer replayed $nfiles corpus inputs"
else
    c2d_failed "corpus replay under libFuzzer"
    tail -n 30 "$work/corpus.log" >&2
fi

rm -rf "$work/smoke"
mkdir -p "$work/smoke"
cp "$corpus"/* "$work/smoke/"
if "$fuzzer" -seed=1 -runs="$runs" -max_total_time=60 -artifact_prefix="$work/" \
    "$work/smoke" >"$work/smoke.log" 2>&1; then
    c2d_passed
    echo "fuzz: smoke run: $(sed -n 's/^Done \([0-9]*\) runs in \([0-9]*\) second.*/\1 executions in \2 s/p' "$work/smoke.log")"
else
    c2d_failed "smoke run (crash input saved in $work/)"
    tail -n 30 "$work/smoke.log" >&2
fi
c2d_summary
