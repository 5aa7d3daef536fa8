#!/usr/bin/env bash
# The code the three headers share (tools/fov_shared.h) stands in each header as regions
# between "/* ==== FOV_SHARED_BEGIN <name>" and "/* ==== FOV_SHARED_END <name>" lines.
# Checks: the same regions in the same order in fovsdf.h, fovlp.h and fovpt.h; each region
# byte-identical in all three pairs; the copies equal the source (tools/sync_shared.py
# --check); a translation unit with all three implementations compiles the shared code once;
# headers of different shared revisions refuse to mix. The comparisons are run on a corrupted
# copy too, where they must fail.
set -u
cd "$(dirname "$0")/.."
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
CC=${CC:-gcc}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

# region names of a file, in order
names() { grep -oE '^/\* ==== FOV_SHARED_(BEGIN|END) [a-z_]+' "$1" | awk '{print $3 == "FOV_SHARED_BEGIN" ? $4 : "/" $4}' | tr '\n' ' '; }
# the text of region $2 of file $1, BEGIN and END lines included
region() { awk -v n="$2" '$0 ~ "^/\\* ==== FOV_SHARED_BEGIN " n "([^a-z_]|$)" {s=1} s {print} s && $0 ~ "^/\\* ==== FOV_SHARED_END " n "([^a-z_]|$)" {exit}' "$1"; }

# compare DIR: 0 when the three headers in DIR hold identical regions in the same order
compare() {
    local d=$1 a b r rc=0
    for a in fovsdf fovlp fovpt; do
        for b in fovsdf fovlp fovpt; do
            [ "$a" \< "$b" ] || continue
            if [ "$(names "$d/$a.h")" != "$(names "$d/$b.h")" ]; then
                echo "  $a.h and $b.h: regions differ: $(names "$d/$a.h") / $(names "$d/$b.h")"; rc=1; continue
            fi
            for r in $(grep -oE '^/\* ==== FOV_SHARED_BEGIN [a-z_]+' "$d/$a.h" | awk '{print $4}'); do
                if ! cmp -s <(region "$d/$a.h" "$r") <(region "$d/$b.h" "$r"); then
                    echo "  region $r differs between $a.h and $b.h"; rc=1
                fi
            done
        done
    done
    return $rc
}

regs=$(names fovsdf.h)
nreg=$(grep -cE '^/\* ==== FOV_SHARED_BEGIN ' fovsdf.h)
if [ "$nreg" -ge 2 ] && [ "$(grep -cE '^/\* ==== FOV_SHARED_END ' fovsdf.h)" -eq "$nreg" ]; then
    ok "fovsdf.h has $nreg shared regions: $regs"
else
    bad "fovsdf.h shared regions: $regs"
fi
if compare .; then ok "the shared regions are byte-identical in fovsdf.h, fovlp.h and fovpt.h (all three pairs)"
else bad "shared regions differ between headers"; fi
if python3 tools/sync_shared.py --check; then ok "the headers' copies equal tools/fov_shared.h (sync_shared.py --check)"
else bad "a header's copy differs from tools/fov_shared.h: run python3 tools/sync_shared.py"; fi
# tools that know nothing but the two words: every line naming them is a marker line, and the
# text from each line containing FOV_SHARED_BEGIN to the next containing FOV_SHARED_END is the
# same in the three headers
stray=$(grep -n 'FOV_SHARED_BEGIN\|FOV_SHARED_END' fovsdf.h fovlp.h fovpt.h | grep -v ':/\* ==== FOV_SHARED_')
plain() { awk '/FOV_SHARED_BEGIN/{on=1} on{print} /FOV_SHARED_END/{on=0}' "$1" | cksum; }
if [ -z "$stray" ] && [ "$(plain fovsdf.h)" = "$(plain fovlp.h)" ] && [ "$(plain fovsdf.h)" = "$(plain fovpt.h)" ]; then
    ok "FOV_SHARED_BEGIN / FOV_SHARED_END appear only on marker lines; a plain scan sees equal blocks"
else
    bad "the marker words appear outside marker lines: ${stray:-a plain scan sees different blocks}"
fi
lines=$(for r in $(grep -oE '^/\* ==== FOV_SHARED_BEGIN [a-z_]+' fovsdf.h | awk '{print $4}'); do region fovsdf.h "$r"; done | wc -l)
if [ "$lines" -ge 300 ]; then ok "shared regions hold $lines lines per header"; else bad "shared regions only $lines lines"; fi

# the checks must catch a corrupted copy: one changed byte in fovlp.h's impl region
mkdir -p "$TMP/repo/tools"
cp fovsdf.h fovlp.h fovpt.h "$TMP/repo/"; cp tools/fov_shared.h tools/sync_shared.py "$TMP/repo/tools/"
awk '/^\/\* ==== FOV_SHARED_BEGIN impl/{s=1} s && /fov__dot\(const float a\[3\]/ && !done {sub(/a\[0\] \* b\[0\]/, "a[0] * b[1]"); done=1} {print}' fovlp.h > "$TMP/x"
# the edit may fall on the signature line; corrupt the body line instead when it did not change
if cmp -s "$TMP/x" fovlp.h; then sed '/^FOV__PRIV float fov__dot/{n;n;s/a\[0\] \* b\[0\]/a[0] * b[1]/}' fovlp.h > "$TMP/x"; fi
cp "$TMP/x" "$TMP/repo/fovlp.h"
if ! cmp -s "$TMP/x" fovlp.h && ! compare "$TMP/repo" >/dev/null && ! python3 "$TMP/repo/tools/sync_shared.py" --check >/dev/null; then
    ok "a one-byte change in fovlp.h's shared region fails both comparisons"
else
    bad "a corrupted shared region went unnoticed"
fi
if python3 "$TMP/repo/tools/sync_shared.py" >/dev/null && compare "$TMP/repo" >/dev/null && cmp -s "$TMP/repo/fovlp.h" fovlp.h; then
    ok "sync_shared.py restores the corrupted copy from tools/fov_shared.h"
else
    bad "sync_shared.py did not restore fovlp.h"
fi

# all three implementations in one translation unit: the shared code is compiled once
printf '#define FOV_IMPL\n#include "fovsdf.h"\n#include "fovlp.h"\n#include "fovpt.h"\nint main(void) { return 0; }\n' > "$TMP/all.c"
if $CC -std=c99 -I. -E "$TMP/all.c" -o "$TMP/all.i" 2>"$TMP/e" &&
   [ "$(grep -c 'fov__ecc_init(fov_ecc_model \*m' "$TMP/all.i")" -eq 1 ] &&
   [ "$(grep -c 'typedef enum fov_result' "$TMP/all.i")" -eq 1 ] &&
   $CC -std=c99 -Wall -Wextra -Werror -I. "$TMP/all.c" -lm -o "$TMP/all" 2>>"$TMP/e"; then
    ok "three implementations in one translation unit: one copy of the shared code"
else
    bad "shared code in one translation unit: $(head -3 "$TMP/e")"
fi
# headers whose shared blocks differ in revision refuse to mix
printf '#define FOV_SHARED_DECL_INCLUDED 1\n#define FOV_SHARED_REVISION 0\n#include "fovsdf.h"\nint main(void) { return 0; }\n' > "$TMP/mix.c"
if ! $CC -std=c99 -I. -c "$TMP/mix.c" -o "$TMP/mix.o" 2>"$TMP/e" && grep -q 'different releases' "$TMP/e"; then
    ok "a shared block of another revision already included: #error"
else
    bad "mixing shared revisions compiled: $(head -2 "$TMP/e")"
fi
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
