# SPDX-License-Identifier: MIT
# stall_scan.awk - reads `objdump -d -M intel --no-show-raw-insn` of one
# object and reports, for the functions on a hot path, every stack load that
# the store buffer cannot forward: a load overlapping an earlier store to
# the frame that does not lie wholly inside the youngest such store (two
# 8-byte stores read back as one 16-byte vector, a 4-byte store read as 8
# bytes, ...).  Such a load waits until the stores have left the buffer,
# some 10-15 cycles on current x86-64 cores (Intel's and AMD's optimisation
# manuals, "store forwarding").  Used by tests/build/normal_stall.sh.
#   -v roots="f g"  the public functions whose hot path is scanned
#   -v cold="h k"   functions the library marks C2D_COLD: calls to them (and
#                   their .part/.isra/.constprop clones) are not followed
# The scan is linear in address order over each function (not per path), so
# it may report a pair on two exclusive branches: stricter, never laxer.
# Prints one line per finding, "FUNC ADDR: load W at BASE+OFF after store
# W' at BASE+OFF'", and nothing when the hot path is clean.
function width(s) {
    if (s ~ /^BYTE/) return 1
    if (s ~ /^WORD/) return 2
    if (s ~ /^DWORD/) return 4
    if (s ~ /^QWORD/) return 8
    if (s ~ /^TBYTE/) return 10
    if (s ~ /^XMMWORD/) return 16
    if (s ~ /^YMMWORD/) return 32
    if (s ~ /^ZMMWORD/) return 64
    return 0
}
function hex(s,    i, v) { # "0x1f" -> 31 (mawk has no strtonum)
    v = 0
    s = tolower(substr(s, 3))
    for (i = 1; i <= length(s); i++) v = v * 16 + index("0123456789abcdef", substr(s, i, 1)) - 1
    return v
}
function base_name(f) { sub(/\..*/, "", f); return f }
BEGIN {
    n = split(roots, r, " ")
    for (i = 1; i <= n; i++) want[r[i]] = 1
    n = split(cold, c, " ")
    for (i = 1; i <= n; i++) iscold[c[i]] = 1
    nf = 0
}
/^[0-9a-f]+ <[^>]+>:$/ {
    fn = $2
    gsub(/[<>:]/, "", fn)
    nf++
    fname[nf] = fn
    nins[fn] = 0
    next
}
/^ +[0-9a-f]+:\t/ && fn != "" {
    line = $0
    sub(/^ +/, "", line)
    k = ++nins[fn]
    ins[fn, k] = line
}
END {
    # The hot set: the roots and whatever they call or jump to, less the cold.
    changed = 1
    while (changed) {
        changed = 0
        for (f in want) {
            for (k = 1; k <= nins[f]; k++) {
                if (ins[f, k] !~ /\t(call|jmp) +[0-9a-f]+ <[^+>]+>$/) continue
                t = ins[f, k]
                sub(/.*</, "", t)
                sub(/>$/, "", t)
                if (t in want || base_name(t) in iscold || !(t in nins)) continue
                want[t] = 1
                changed = 1
            }
        }
    }
    for (f in want) {
        ns = 0
        delta = 0
        for (k = 1; k <= nins[f]; k++) {
            l = ins[f, k]
            split(l, part, "\t")
            addr = part[1]
            sub(/:$/, "", addr)
            text = part[2]
            mnem = text
            sub(/ .*/, "", mnem)
            ops = text
            sub(/^[^ ]+ +/, "", ops)
            if (mnem == "push") { delta -= 8; continue }
            if (mnem == "pop") { delta += 8; continue }
            if (mnem == "sub" && ops ~ /^rsp,0x[0-9a-f]+$/) { delta -= hex(substr(ops, 5)); continue }
            if (mnem == "add" && ops ~ /^rsp,0x[0-9a-f]+$/) { delta += hex(substr(ops, 5)); continue }
            if (mnem == "lea" || mnem ~ /^nop/) continue
            if (!match(ops, /(BYTE|WORD|DWORD|QWORD|TBYTE|XMMWORD|YMMWORD|ZMMWORD) PTR \[(rsp|rbp)([+-]0x[0-9a-f]+)?\]/))
                continue
            m = substr(ops, RSTART, RLENGTH)
            w = width(m)
            reg = m
            sub(/.*\[/, "", reg)
            sub(/[]+-].*/, "", reg)
            off = 0
            if (match(m, /[+-]0x[0-9a-f]+\]/)) {
                o = substr(m, RSTART + 1, RLENGTH - 2)
                off = hex(o)
                if (substr(m, RSTART, 1) == "-") off = -off
            }
            if (reg == "rsp") off += delta
            is_store = index(ops, m) == 1 && mnem !~ /^(v?u?comis|cmp|test|bt)/
            if (is_store) {
                ns++
                sreg[ns] = reg; slo[ns] = off; shi[ns] = off + w
                continue
            }
            for (j = ns; j >= 1; j--) {
                if (sreg[j] != reg || shi[j] <= off || slo[j] >= off + w) continue
                if (off < slo[j] || off + w > shi[j])
                    printf "%s %s: load %d at %s%+d after store %d at %s%+d\n", f, addr, w, reg, off,
                        shi[j] - slo[j], reg, slo[j]
                break
            }
        }
    }
}
