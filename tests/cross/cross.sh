#!/bin/sh
# SPDX-License-Identifier: MIT
# cross.sh check|write OUTDIR DOC  NAME DESCRIPTION COMMAND ...
#   Runs every target's determinism hash (tests/build/hash_cases.c: the same
#   100,000 cases everywhere) at once, each COMMAND under a timeout, then
#   requires of every target that each variant it hashes (and the inputs)
#   equal the first target's, x86-64 of this same run, and of x86-64 that it
#   equals the table in DOC.  `write` first rewrites that table (between its
#   two marker lines) from this run, when every target agrees.
#   Each COMMAND prints lines "...: VARIANT hash H" (VARIANT: inputs, double,
#   float, Q16.16, and for the models model-inputs, rough-double,
#   rough-float, accel-double, accel-float, and the world's, "world"), as
#   hash_vectors and hash_mcu do.
# Prints one line per target, then "cross: N passed, N failed".
set -u
[ $# -ge 6 ] || { echo "usage: cross.sh check|write OUTDIR DOC NAME DESCRIPTION COMMAND ..." >&2; exit 2; }
mode=$1 out=$2 doc=$3
shift 3
case $mode in check | write) ;; *) echo "cross.sh: mode must be check or write, not '$mode'" >&2; exit 2 ;; esac
mkdir -p "$out"
. tests/harness/tally.sh
c2d_tally_name=cross
begin='<!-- hash table: begin (written by `make determinism-table`, tests/cross/cross.sh) -->'
end='<!-- hash table: end -->'
variants="inputs double float Q16.16"
# The models' hashes, over their own case stream (hash_cases.h).
models="model-inputs rough-double rough-float accel-double accel-float"
# The world's, over its own scenes, where it is compiled in (not without
# double); the firmware's 4-byte pointers make c2d_world_bytes smaller, so
# they print only "world-portable" (the same without it).
world="world world-portable"

# Start every run; each writes OUTDIR/NAME.txt and OUTDIR/NAME.rc.
names=""
set -- "$@"
while [ $# -ge 3 ]; do
    name=$1 cmd=$3
    printf '%s\n' "$2" >"$out/$name.desc"
    names="$names $name"
    # shellcheck disable=SC2086
    { timeout -k 5 "${C2D_CROSS_TIMEOUT:-600}" $cmd >"$out/$name.txt" 2>&1; echo $? >"$out/$name.rc"; } &
    shift 3
done
wait

hash_of() { # NAME VARIANT: the hash a run printed, or nothing
    sed -n "s/^.*: $2 hash \([0-9a-f]\{16\}\)\$/\1/p" "$out/$1.txt" | tail -n 1
}
hashed() { # NAME: the variants and models a run hashed (inputs excluded)
    for v in double float Q16.16 rough-double rough-float accel-double accel-float world world-portable; do
        [ -n "$(hash_of "$1" "$v")" ] && printf '%s ' "$v"
    done
}
documented() { # VARIANT: its hash in DOC's table
    awk -v b="$begin" -v e="$end" -v v="$1" '$0 == b { on = 1 } $0 == e { on = 0 }
        on && $1 == "|" && $2 == v && $3 == "|" { gsub(/`/, "", $4); print $4; exit }' "$doc" 2>/dev/null
}

ref=${names# }
ref=${ref%% *}
verdicts=""
for name in $names; do
    rc=$(cat "$out/$name.rc")
    got=$(hashed "$name")
    if [ "$rc" -ne 0 ] || [ -z "$got" ] || [ -z "$(hash_of "$name" inputs)" ] ||
        [ -z "$(hash_of "$name" model-inputs)" ]; then
        c2d_failed "$name: the run failed (exit status $rc); its output:"
        tail -n 5 "$out/$name.txt" >&2
        verdicts="$verdicts $name=failed"
        continue
    fi
    differ=""
    for v in inputs model-inputs $got; do
        [ "$(hash_of "$name" "$v")" = "$(hash_of "$ref" "$v")" ] || differ="$differ $v"
    done
    if [ "$name" = "$ref" ]; then
        c2d_passed
        echo "cross: $name ($(cat "$out/$name.desc")): $(for v in $variants $models $world; do
            printf '%s %s  ' "$v" "$(hash_of "$name" "$v")"; done)"
    elif [ -z "$differ" ]; then
        c2d_passed
        echo "cross: $name ($(cat "$out/$name.desc")): ${got% } identical to $ref"
    else
        c2d_failed "$name ($(cat "$out/$name.desc")): differs from $ref in${differ}:"
        for v in $differ; do echo "cross:   $v $(hash_of "$name" "$v") against $(hash_of "$ref" "$v")" >&2; done
        verdicts="$verdicts $name=differs"
    fi
done

if [ "$mode" = write ]; then
    if [ -n "$verdicts" ]; then
        c2d_failed "not writing $doc: targets disagree or failed:$verdicts"
    else
        table=$out/table.md
        {
            echo "$begin"
            echo "| variant | hash of the 100,000 cases (models: of their 20,000; world: of its scenes) |"
            echo "|---|---|"
            for v in $variants $models $world; do echo "| $v | \`$(hash_of "$ref" "$v")\` |"; done
            echo
            echo "| target | built and run | variants hashed | result |"
            echo "|---|---|---|---|"
            for name in $names; do
                r="identical to $ref"
                [ "$name" = "$ref" ] && r=reference
                echo "| $name | $(cat "$out/$name.desc") | $(hashed "$name" | sed 's/ $//; s/ /, /g') | $r |"
            done
            echo "$end"
        } >"$table"
        if grep -qxF "$begin" "$doc" && grep -qxF "$end" "$doc"; then
            awk -v b="$begin" -v e="$end" -v t="$table" '
                $0 == b { while ((getline line < t) > 0) print line; skip = 1; next }
                $0 == e { skip = 0; next }
                !skip' "$doc" >"$doc.tmp" && mv "$doc.tmp" "$doc"
        else
            { echo; cat "$table"; } >>"$doc"
        fi
        echo "cross: wrote the table in $doc"
    fi
fi

# The reference against the published table.
missing="" differ=""
for v in $(hashed "$ref") inputs model-inputs; do
    d=$(documented "$v")
    if [ -z "$d" ]; then missing="$missing $v"; elif [ "$d" != "$(hash_of "$ref" "$v")" ]; then differ="$differ $v"; fi
done
if [ -z "$missing$differ" ]; then
    c2d_passed
    echo "cross: $ref matches the table in $doc"
else
    c2d_failed "$ref against $doc:${missing:+ not in the table:$missing}${differ:+ different:$differ}"
    echo "cross: if the library's results changed on purpose, \`make determinism-table\` rewrites the table" >&2
fi
c2d_summary
