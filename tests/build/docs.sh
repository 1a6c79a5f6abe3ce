#!/bin/sh
# SPDX-License-Identifier: MIT
# docs.sh [FILE.md...] - the documentation's own contract, run by `make test`
# (tests/build/build.mk, make check-docs), from the top of the tree:
#   - README.md is at most 12,000 bytes (it is the front page; the detail
#     lives in docs/)
#   - every relative link and image in README.md, docs/*.md and
#     lib/real/toia/README.md (or the FILEs given) resolves: the file or
#     directory exists, and an anchor (#name, in the same page or another
#     .md) is the GitHub slug of one of that page's headings: lowercased,
#     characters other than letters, digits, spaces, "-" and "_" removed,
#     spaces as "-", a repeated heading's slug suffixed -1, -2, ...
# Links inside code (fenced blocks, `spans`) are not links; http(s):,
# mailto: and other schemes are not checked (no network).  One check per
# link and one for the size; prints "docs: N passed, M failed"
# (tests/harness/tally.sh), each failure as "docs: FAILED FILE:LINE: ...".
set -u
. tests/harness/tally.sh
c2d_tally_name=docs
readme_max=12000

[ $# -gt 0 ] || set -- README.md docs/*.md lib/real/toia/README.md

size=$(wc -c <README.md)
if [ "$size" -le "$readme_max" ]; then
    c2d_passed
    echo "docs: README.md is $size bytes (at most $readme_max)"
else
    c2d_failed "README.md is $size bytes, more than $readme_max: move detail into docs/"
fi

# The links, one line each: "ok FILE:LINE TARGET" or "FAIL FILE:LINE TARGET: WHY".
results=$(python3 - "$@" <<'PY'
import os
import re
import sys
import unicodedata

FENCE = re.compile(r"^ {0,3}(`{3,}|~{3,})")


def blank_fences(text):
    """The text with fenced code blocks replaced by spaces, newlines kept, so
    that offsets still give line numbers."""
    out, fence = [], None
    for line in text.splitlines(keepends=True):
        m = FENCE.match(line)
        if fence is None and m:
            fence = m.group(1)[0] * len(m.group(1))
            out.append(re.sub(r"[^\n]", " ", line))
        elif fence is not None:
            if line.strip().startswith(fence):
                fence = None
            out.append(re.sub(r"[^\n]", " ", line))
        else:
            out.append(line)
    return "".join(out)


def blank_code(text):
    """blank_fences, and inline code spans too."""
    text = blank_fences(text)
    return re.sub(r"(`+)(?:(?!\1).)+?\1", lambda m: re.sub(r"[^\n]", " ", m.group(0)), text, flags=re.S)


def slug(heading):
    """GitHub's anchor for a heading (its text as rendered)."""
    t = re.sub(r"!?\[([^\]]*)\]\([^)]*\)", r"\1", heading)  # links: their text
    t = re.sub(r"<[^>]+>", "", t)  # inline HTML
    t = t.replace("`", "").strip().lower()
    keep = []
    for ch in t:
        cat = unicodedata.category(ch)
        if ch in " -_" or cat[0] in "LMN" or cat == "Pc":
            keep.append(ch)
    return "".join(keep).replace(" ", "-")


def anchors(path, cache={}):
    if path not in cache:
        seen, found = {}, set()
        with open(path, encoding="utf-8") as f:
            text = blank_fences(f.read())  # a heading's `code` is part of its text
        for line in text.splitlines():
            m = re.match(r"^ {0,3}#{1,6}[ \t]+(.*?)[ \t]*#*[ \t]*$", line)
            if not m:
                continue
            s = slug(m.group(1))
            n = seen.get(s, 0)
            seen[s] = n + 1
            found.add(s if n == 0 else f"{s}-{n}")
        cache[path] = found
    return cache[path]


LINK = re.compile(r"\]\(\s*<?([^)\s>]*)>?(?:\s+(?:\"[^\"]*\"|'[^']*'))?\s*\)")
REFDEF = re.compile(r"^ {0,3}\[[^\]]+\]:\s*<?(\S+?)>?(?:\s|$)", re.M)

for md in sys.argv[1:]:
    with open(md, encoding="utf-8") as f:
        text = blank_code(f.read())
    targets = [(m.start(1), m.group(1)) for m in LINK.finditer(text)]
    targets += [(m.start(1), m.group(1)) for m in REFDEF.finditer(text)]
    for pos, target in sorted(targets):
        where = f"{md}:{text.count(chr(10), 0, pos) + 1}"
        if not target or re.match(r"^[A-Za-z][A-Za-z0-9+.-]*:", target) or target.startswith("//"):
            continue  # a scheme: not checked
        path, _, anchor = target.partition("#")
        dest = os.path.normpath(os.path.join(os.path.dirname(md), path)) if path else md
        why = None
        if not os.path.exists(dest):
            why = f"no such file or directory ({dest})"
        elif anchor:
            if not dest.endswith(".md") or os.path.isdir(dest):
                why = f"an anchor into {dest}, which is not a Markdown page"
            elif anchor not in anchors(dest):
                why = f"no heading of {dest} has the anchor #{anchor}"
        print(f"ok {where} {target}" if why is None else f"FAIL {where} {target}: {why}")
PY
) || { c2d_failed "the link check itself (python3) failed"; c2d_summary; exit 1; }

links=0
while IFS= read -r line; do
    case $line in
    "ok "*) c2d_passed; links=$((links + 1)) ;;
    "FAIL "*) c2d_failed "${line#FAIL }"; links=$((links + 1)) ;;
    esac
done <<EOF
$results
EOF
echo "docs: $links relative links and anchors in $# files"
c2d_summary
