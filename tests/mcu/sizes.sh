#!/bin/sh
# SPDX-License-Identifier: MIT
# One target's section of the size table (build/mcu/SIZES.md, which make
# cross compares with docs/SIZES.md and make sizes copies there), from the
# library object built with -ffunction-sections -fstack-usage
# -fcallgraph-info=su.
# Fails (exit 1, reason on stderr) when the object takes any outside symbol
# other than compiler-runtime helpers and sqrt/sqrtf, when the call graph has
# a cycle (recursion), an indirect call outside the world or a dynamically
# sized frame, and on the target-specific checks given as options.  The
# world's indirect calls are the caller's callbacks (on_event, resolvers,
# broadphase): its functions' stack is the library's part, "+ callbacks".
#
# Usage: sizes.sh [--forbid REGEX] [--inline SYMBOL=INSN]... [--profile FUNCTION]...
#                 [--rows FILE] NAME DESCRIPTION OBJECT CC ARCH-FLAGS...
#   --forbid REGEX        no outside symbol may match (e.g. '^__aeabi_d')
#   --inline SYMBOL=INSN  SYMBOL must not be called, INSN must be in the code
#   --profile FUNCTION    where the bytes go: the source files and largest
#                         symbols of FUNCTION's closure with its helpers
#                         (`library`: of all public functions linked)
#   --rows FILE           append this target's summary row to FILE
set -eu

forbid='' inline='' profile='' rows=/dev/null
while [ $# -gt 0 ]; do
    case $1 in
    --forbid) forbid=$2; shift 2 ;;
    --inline) inline="$inline $2"; shift 2 ;;
    --profile) profile="$profile $2"; shift 2 ;;
    --rows) rows=$2; shift 2 ;;
    *) break ;;
    esac
done
name=$1 desc=$2 obj=$3 cc=$4
shift 4
arch="$*"
tools=${cc%gcc}
base=${obj%.o}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
status=0
fail() {
    echo "cross $name: FAIL: $*" >&2
    status=1
}

# ------------------------------------------------------------ outside symbols
# Helpers are whatever this multilib's libgcc defines.  memcpy and friends
# are what GCC requires of any freestanding environment (it may emit calls
# to them for struct copies); the library avoids them, so they fail too.
libgcc=$($cc $arch -print-libgcc-file-name)
"${tools}nm" -g --defined-only "$libgcc" 2>/dev/null | awk 'NF == 3 { print $3 }' | sort -u >"$tmp/libgcc"
"${tools}nm" -u "$obj" | awk '{ print $NF }' | sort -u >"$tmp/undef"
helpers='' libm='' freestanding='' other=''
for s in $(cat "$tmp/undef"); do
    if grep -qx "$s" "$tmp/libgcc"; then
        helpers="$helpers $s"
    else
        case $s in
        sqrt | sqrtf) libm="$libm $s" ;;
        memcpy | memmove | memset | memcmp) freestanding="$freestanding $s" ;;
        *) other="$other $s" ;;
        esac
    fi
done
[ -z "$other" ] || fail "outside symbols that are neither compiler helpers nor sqrt/sqrtf:$other"
# The library promises no C library at all: a struct copy that became a
# memcpy call is a regression (pass such structs by pointer).
[ -z "$freestanding" ] || fail "calls into the C library's memory functions:$freestanding"
if [ -n "$forbid" ]; then
    bad=$(grep -E "$forbid" "$tmp/undef" | tr '\n' ' ' || true)
    [ -z "$bad" ] || fail "forbidden outside symbols (/$forbid/): $bad"
fi
"${tools}objdump" -d "$obj" >"$tmp/dis"
for pair in $inline; do
    sym=${pair%%=*} insn=${pair#*=}
    if grep -qx "$sym" "$tmp/undef"; then
        fail "$sym is still called (needs -fno-math-errno and a builtin square root)"
    fi
    grep -q "[[:space:]]$insn[[:space:]]" "$tmp/dis" || fail "no $insn instruction in the code"
done

# ------------------------------------------------------------ call graph
# Worst-case stack per function: its own frame plus the deepest chain of
# library callees (compiler helpers and sqrt are leaves of a few words and
# are not counted).  A cycle is recursion: reported and failed.
# Identical code folding (-fipa-icf, on at -Os) can make one static function
# an alias of another: the call graph then names a callee it has no node
# for.  Aliases share section and address in the symbol table.
"${tools}readelf" -sW "$obj" | awk '$4 == "FUNC" { k = $7 " " $2; if (k in first) print $8, first[k]; else first[k] = $8 }' >"$tmp/alias"
awk '
FILENAME == ARGV[1] { alias[$1] = $2; next }
function quoted(line, key,   i, r) {
    i = index(line, key ": \""); if (i == 0) return ""
    r = substr(line, i + length(key) + 3); return substr(r, 1, index(r, "\"") - 1)
}
function first_line(label) { return index(label, "\\") ? substr(label, 1, index(label, "\\") - 1) : label }
function worst(n,   i, c, w, best) {
    if (n in done) return done[n]
    if (n in active) { print "RECURSION " fn[n]; return 0 }
    active[n] = 1; best = 0
    for (i = 1; i <= nout[n]; i++) {
        c = to[n, i]
        if (!(c in fn)) continue
        w = worst(c); if (w > best) best = w
    }
    delete active[n]; done[n] = own[n] + best; return done[n]
}
function collect(n,   i, c) {
    if (n in seen) return
    seen[n] = 1
    for (i = 1; i <= nout[n]; i++) {
        c = to[n, i]
        if (c in fn) collect(c); else if (c == "__indirect_call") calls_back = 1; else found[c in ext ? ext[c] : c] = 1
    }
}
/^node:/ {
    t = quoted($0, "title"); lab = quoted($0, "label")
    if ($0 ~ /shape : ellipse/) { e = first_line(lab); sub(/^__builtin_/, "", e); ext[t] = e; next }
    fn[t] = first_line(lab); own[t] = 0
    if (match(lab, /n[0-9]+ bytes \(/)) own[t] = substr(lab, RSTART + 1, RLENGTH - 9) + 0
    if (lab ~ /\(dynamic/ && lab !~ /bounded/) print "DYNAMIC " fn[t]
}
/^edge:/ {
    s = quoted($0, "sourcename"); d = quoted($0, "targetname")
    nout[s]++; to[s, nout[s]] = d
    if (d == "__indirect_call" && fn[s] !~ /^c2d_(w|world)_/) print "INDIRECT " fn[s]
}
END {
    for (t in fn) byname[fn[t]] = t
    for (s in nout) for (i = 1; i <= nout[s]; i++) {
        c = to[s, i]; n = substr(c, index(c, ":") + 1)
        if (!(c in fn) && !(c in ext) && index(c, ":") > 0 && (n in alias) && (alias[n] in byname))
            to[s, i] = byname[alias[n]]
        else if (!(c in fn) && !(c in ext) && index(c, ":") > 0)
            print "UNRESOLVED " n
    }
    for (t in fn) {
        if (index(t, ":") > 0) continue
        w = worst(t)
        split("", seen); split("", found); calls_back = 0; collect(t); list = ""
        for (e in found) list = list " " e
        print "STACK " fn[t] " " own[t] " " w (calls_back ? "+" : "") list
    }
}' "$tmp/alias" "$base.ci" >"$tmp/graph"
grep '^RECURSION ' "$tmp/graph" | sort -u | while read -r _ f; do echo "cross $name: FAIL: recursion through $f" >&2; done
grep -q '^RECURSION ' "$tmp/graph" && status=1
grep -q '^UNRESOLVED ' "$tmp/graph" && fail "callee without a call-graph node: $(grep '^UNRESOLVED ' "$tmp/graph" | cut -d' ' -f2 | sort -u | tr '\n' ' ')"
grep -q '^INDIRECT ' "$tmp/graph" && fail "indirect call outside the world's callbacks (stack not bounded statically): $(grep '^INDIRECT ' "$tmp/graph" | cut -d' ' -f2 | sort -u | tr '\n' ' ')"
grep -q '^DYNAMIC ' "$tmp/graph" && fail "dynamically sized stack frame: $(grep '^DYNAMIC ' "$tmp/graph" | cut -d' ' -f2 | tr '\n' ' ')"

# ------------------------------------------------------------ sizes
# A function's cost is what a firmware linking only it would carry: its
# closure in the library (--gc-sections from it as the entry), then the
# libgcc helpers that closure pulls in.  Outside symbols stay unresolved.
text_of() { "${tools}size" "$1" | awk 'NR == 2 { print $1 }'; }
link() {
    out=$1
    shift
    $cc $arch -nostdlib -Wl,--gc-sections -Wl,--unresolved-symbols=ignore-all -o "$out" "$@"
}
# Public: global default-visibility functions (the hidden ones are the
# library's own, lib/internal.h).
"${tools}readelf" -sW "$obj" | awk '$4 == "FUNC" && $5 == "GLOBAL" && $6 == "DEFAULT" && $7 != "UND" { print $8 }' |
    sort >"$tmp/public"
set -- $("${tools}size" "$obj" | awk 'NR == 2 { print $1, $2, $3 }')
obj_text=$1 obj_data=$2 obj_bss=$3
all_entry=$(head -n 1 "$tmp/public")
undefs=$(sed 's/^/-Wl,--undefined=/' "$tmp/public" | tr '\n' ' ')
link "$tmp/all.elf" -Wl,-e,"$all_entry" $undefs "$obj"
link "$tmp/allh.elf" -Wl,-e,"$all_entry" $undefs "$obj" -lgcc
all_code=$(text_of "$tmp/all.elf")
all_total=$(text_of "$tmp/allh.elf")
worst_stack=0
# A part of the library (the world, the sphere contacts): the code linking
# only its functions brings in, and what it adds to all the others linked.
part_code() { # FILE-OF-FUNCTIONS
    $cc $arch -nostdlib -Wl,--gc-sections -Wl,--unresolved-symbols=ignore-all -o "$tmp/part.elf" \
        -Wl,-e,"$(head -n 1 "$1")" $(sed 's/^/-Wl,--undefined=/' "$1" | tr '\n' ' ') "$obj"
    text_of "$tmp/part.elf"
}
part_rows() { # REGEX DESCRIPTION
    grep -E "$1" "$tmp/public" >"$tmp/part" || return 0
    grep -vE "$1" "$tmp/public" >"$tmp/rest"
    code=$(part_code "$tmp/part")
    rest=$(part_code "$tmp/rest")
    echo "| $2 | $code | 0 | 0 |"
    echo "| what it adds to all the other public functions linked | $((all_code - rest)) | 0 | 0 |"
}

echo "### $name: $desc"
echo
echo "\`$cc $arch\`"
echo
echo "| | text | data | bss |"
echo "|---|---:|---:|---:|"
echo "| library object | $obj_text | $obj_data | $obj_bss |"
echo "| all public functions linked (--gc-sections) | $all_code | 0 | 0 |"
echo "| the same with the libgcc helpers it pulls in | $all_total | 0 | 0 |"
part_rows '^c2d_world_' 'the event-driven world: its functions linked (with the calls it makes)'
part_rows '^c2d_collide_(balls|cushion)f?$' 'the sphere contacts: `c2d_collide_balls`, `c2d_collide_cushion` (and `f`) linked'
part_rows '^c2d_time_of_impact_accelf?$' 'the accelerated time of impact: `c2d_time_of_impact_accel` (and `f`) linked'
echo
echo "| function | code | + helpers | stack | compiler helpers and outside symbols called |"
echo "|---|---:|---:|---:|---|"
for f in $(cat "$tmp/public"); do
    link "$tmp/f.elf" -Wl,-e,"$f" "$obj"
    link "$tmp/fh.elf" -Wl,-e,"$f" "$obj" -lgcc
    code=$(text_of "$tmp/f.elf")
    total=$(text_of "$tmp/fh.elf")
    line=$(grep "^STACK $f " "$tmp/graph" || echo "STACK $f ? ?")
    stack=$(echo "$line" | cut -d' ' -f4)
    called=$(echo "$line" | cut -d' ' -f5- | tr ' ' '\n' | sed '/^$/d' | sort -u | sed 's/.*/`&`/' | tr '\n' ' ' | sed 's/ $//')
    [ "${stack%+}" != "?" ] && [ "${stack%+}" -gt "$worst_stack" ] && worst_stack=${stack%+}
    [ "${stack%+}" = "$stack" ] || stack="${stack%+} + callbacks"
    echo "| \`$f\` | $code | $((total - code)) | $stack | ${called:--} |"
done
echo

# ------------------------------------------------------------ where the bytes go
# The linked closure's functions (nm -S: their sizes, alignment padding
# aside), each charged to the lib/ file that defines it: its name without
# the instance suffix (_f64, _f32) and gcc's clone suffixes (.constprop.0,
# .part.0, .isra.0), found as a definition in lib/; libgcc's helpers as one
# group.  The largest symbols follow (the helpers among them as well).
src=$(cd "$(dirname "$0")/../.." && pwd)
for f in $(cd "$src" && find lib -name '*.[ch]' | sort); do
    # A definition: a line at column 0 naming c2d_...( whose declaration
    # reaches a brace before a semicolon.
    awk -v file="${f#lib/}" '
    cand == "" && /^[A-Za-z_]/ && match($0, /c2d_[A-Za-z0-9_]*[(]/) { cand = substr($0, RSTART, RLENGTH - 1) }
    cand != "" {
        b = index($0, "{"); c = index($0, ";")
        if (b && (!c || b < c)) { print cand, file; cand = "" } else if (c) cand = ""
    }' "$src/$f"
done | awk '!($1 in f) { f[$1] = 1; print }' >"$tmp/defs"
profile_of() { # ELF TITLE
    "${tools}nm" -S --size-sort "$1" | awk 'NF == 4 && $3 ~ /^[tTwW]$/ { print $1, $2, $4 }' >"$tmp/syms"
    awk -v title="$2" -v rows="$tmp/rows" -v top="$tmp/top" '
    FILENAME == ARGV[1] { file[$1] = $2; next }
    function hex(h,   i, v) {
        v = 0; h = tolower(h)
        for (i = 1; i <= length(h); i++) v = v * 16 + index("0123456789abcdef", substr(h, i, 1)) - 1
        return v
    }
    {
        n = hex($2); s = $3
        if ($1 in seen) next # an alias (folded identical code, libgcc entry points) counts once
        seen[$1] = 1
        b = s; sub(/[.].*$/, "", b); sub(/_f(32|64)$/, "", b)
        f = (b in file) ? "`lib/" file[b] "`" : (s ~ /^c2d_/ ? "(not found in lib/)" : "libgcc helpers")
        bytes[f] += n; count[f]++; total += n; nsym++
        printf "%d\t`%s`\t%s\n", n, s, f >top
    }
    END {
        for (f in bytes) printf "%d\t%s\t%.1f %%\t%d\n", bytes[f], f, 100 * bytes[f] / total, count[f] >rows
        printf "%s: %d bytes in %d functions.\n", title, total, nsym
    }' "$tmp/defs" "$tmp/syms"
    echo
    echo "| file | bytes | share | functions |"
    echo "|---|---:|---:|---:|"
    sort -t "$(printf '\t')" -k1,1nr -k2,2 "$tmp/rows" | awk -F '\t' '{ printf "| %s | %d | %s | %d |\n", $2, $1, $3, $4 }'
    echo
    echo "| largest symbols | bytes | file |"
    echo "|---|---:|---|"
    sort -t "$(printf '\t')" -k1,1nr -k2,2 "$tmp/top" | head -n 15 | awk -F '\t' '{ printf "| %s | %d | %s |\n", $2, $1, $3 }'
    rm -f "$tmp/rows" "$tmp/top"
}
list() { if [ -n "$1" ]; then echo "$1" | tr ' ' '\n' | sed '/^$/d' | sed 's/.*/`&`/' | tr '\n' ' ' | sed 's/ $//'; else echo "none"; fi; }
echo "Outside symbols: compiler helpers (libgcc): $(list "$helpers")"
echo "C library: $(list "$libm")"
echo "GCC freestanding requirements: $(list "$freestanding")"
if [ -n "$other" ]; then echo "**Not allowed:** $(list "$other")"; fi
echo
if [ -n "$profile" ]; then
    echo "#### Where the bytes go"
    echo
    echo "Each function's bytes charged to the lib/ file defining it (what gcc inlined counts where it landed);"
    echo "sizes from the symbol table (nm -S), without alignment padding."
    echo
    for f in $profile; do
        if [ "$f" = library ]; then
            profile_of "$tmp/allh.elf" "All public functions linked, with the libgcc helpers"
        else
            link "$tmp/p.elf" -Wl,-e,"$f" "$obj" -lgcc
            profile_of "$tmp/p.elf" "\`$f\` linked alone, with the libgcc helpers"
        fi
        echo
    done
fi

outside=$(echo $libm $freestanding)
printf '| %s | %s | %s | %s | %s | %s | %s | %s |\n' "$name" "$desc" "$obj_text" "$obj_data" "$obj_bss" \
    "$all_total" "$worst_stack" "${outside:-none}" >>"$rows"
exit $status
