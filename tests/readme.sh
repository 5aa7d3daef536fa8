#!/usr/bin/env bash
# tests/readme.sh - the README stays what a first-time user needs, and its figures are
# generated:
#   - README.md has at most 250 lines;
#   - the three quick starts ("## Quick start: fovsdf.h", "... fovlp.h", "... fovpt.h")
#     exist and start within its first 120 lines;
#   - every ```c block that follows a line "<!-- compile -->" is a complete program: it is
#     compiled with gcc -std=c99 $WARN -Werror and as C++ with g++, and both binaries run
#     and exit 0 (at least three such blocks: the quick starts);
#   - every image and every other relative link of the README names an existing file;
#   - bench/README.md is what bench/sdf_tables.py, bench/lp_tables.py, bench/pt_tables.py and
#     bench/perceptual_tables.py write from the committed CSVs (run on a copy, then diffed).
# Prints PASS/FAIL lines and "N passed, N failed"; exit 1 on a failure.
# README=path and BENCH_README=path check other files (used to try that each check fails).
set -u
cd "$(dirname "$0")/.."
README=${README:-README.md}
BENCH_README=${BENCH_README:-bench/README.md}
CC=${CC:-gcc}
CXX=${CXX:-g++}
WARN="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Werror -ffp-contract=off"
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
P=0
F=0
ok() { echo "PASS $*"; P=$((P + 1)); }
bad() { echo "FAIL $*"; F=$((F + 1)); }

# 1. length
n=$(wc -l <"$README")
if [ "$n" -le 250 ]; then ok "README length: $n lines (<= 250)"; else bad "README length: $n lines (> 250)"; fi

# 2. the quick starts, up front
for h in fovsdf.h fovlp.h fovpt.h; do
    l=$(grep -n -F -x "## Quick start: $h" "$README" | head -1 | cut -d: -f1)
    if [ -z "$l" ]; then bad "quick start $h: no line '## Quick start: $h'"
    elif [ "$l" -le 120 ]; then ok "quick start $h at line $l (<= 120)"
    else bad "quick start $h at line $l (> 120)"; fi
done

# 3. the marked programs: extract, compile as C and C++, run
awk -v dir="$TMP" '
    /^<!-- compile -->[ \t]*$/ { want = 1; next }
    want && /^```c[ \t]*$/ { n++; f = sprintf("%s/block%d.c", dir, n); inblk = 1; want = 0; next }
    inblk && /^```[ \t]*$/ { inblk = 0; close(f); next }
    inblk { print > f; next }
    want && NF { want = 0 }
' "$README"
nb=$(ls "$TMP"/block*.c 2>/dev/null | wc -l)
if [ "$nb" -ge 3 ]; then ok "README: $nb programs marked <!-- compile -->"; else bad "README: $nb programs marked <!-- compile --> (< 3)"; fi
# compiled JOBS at a time (with the gallery of 4b), then checked and run in order
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
bgc() { # LOG RC_FILE COMMAND...: a compile in the background, its exit status into RC_FILE
    local log=$1 rcf=$2; shift 2
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    ( "$@" >"$log" 2>&1; echo $? >"$rcf" ) &
}
for src in "$TMP"/block*.c; do
    [ -e "$src" ] || continue
    b=$(basename "$src" .c)
    bgc "$TMP/$b.log" "$TMP/$b.rc" $CC -std=c99 -O1 $WARN -I. "$src" -lm -o "$TMP/$b"
    bgc "$TMP/${b}_cxx.log" "$TMP/${b}_cxx.rc" $CXX -x c++ -O1 $WARN -I. "$src" -lm -o "$TMP/${b}_cxx"
done
bgc "$TMP/gallery.log" "$TMP/gallery.rc" $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O2 $WARN -I. examples/gallery.c -lm -o "$TMP/gallery"
wait
for src in "$TMP"/block*.c; do
    [ -e "$src" ] || continue
    b=$(basename "$src" .c)
    first=$(grep -m1 -E '^#include "fov' "$src" | sed 's/.*"\(.*\)".*/\1/')
    what="README $b ($first)"
    if [ "$(cat "$TMP/$b.rc" 2>/dev/null)" = 0 ]; then
        ok "$what compiles as C99"
        if timeout 120 "$TMP/$b" >/dev/null 2>"$TMP/$b.err"; then ok "$what runs, exit 0"
        else bad "$what exits with status $? ($(head -c 200 "$TMP/$b.err"))"; fi
    else bad "$what does not compile as C99:"; head -15 "$TMP/$b.log" | sed 's/^/    /'; fi
    if [ "$(cat "$TMP/${b}_cxx.rc" 2>/dev/null)" = 0 ]; then
        ok "$what compiles as C++"
        if timeout 120 "$TMP/${b}_cxx" >/dev/null 2>&1; then ok "$what (C++) runs, exit 0"
        else bad "$what (C++) exits with status $?"; fi
    else bad "$what does not compile as C++:"; head -15 "$TMP/${b}_cxx.log" | sed 's/^/    /'; fi
done

# 4. images: ![alt](path) and <img src="path">, relative to the README
dir=$(dirname "$README")
imgs=$( { grep -o '!\[[^]]*\]([^)]*)' "$README" | sed 's/.*](\([^)]*\))/\1/'
          grep -o '<img [^>]*src="[^"]*"' "$README" | sed 's/.*src="\([^"]*\)"/\1/'; } | sed 's/[ #?].*//' | sort -u)
ni=0
for i in $imgs; do
    ni=$((ni + 1))
    if [ -f "$dir/$i" ]; then ok "image $i exists"; else bad "image $i: no such file"; fi
done
[ "$ni" -ge 1 ] || bad "README links no image"
# and every other relative link ([text](path), not http(s) or #anchor) names an existing file
for i in $(grep -o -E '(^|[^!])\[[^]]*\]\([^)]*\)' "$README" | sed 's/.*](\([^)]*\))/\1/' | grep -v -E '^(https?:|mailto:|#)' \
           | sed 's/#.*//' | sort -u); do
    if [ -e "$dir/$i" ]; then ok "link $i exists"; else bad "link $i: no such file"; fi
done

# 4b. the gallery program builds warning-free and runs (at 48x27 panels; `make gallery` renders
#     docs/img/ at 480x270 and is not rerun here: a full render takes a CPU-minute)
#     (compiled above, with the README's programs)
if [ "$(cat "$TMP/gallery.rc" 2>/dev/null)" = 0 ]; then
    ok "examples/gallery.c builds with -Werror"
    mkdir -p "$TMP/gal"
    if "$TMP/gallery" --out "$TMP/gal" --width 48 --height 27 >/dev/null 2>&1 \
       && [ "$(ls "$TMP"/gal/*.ppm 2>/dev/null | wc -l)" -eq 5 ] \
       && [ "$(head -n 3 "$TMP/gal/pt_cornell.ppm")" = "$(printf 'P6\n152 27\n255')" ]; then
        ok "gallery writes its 5 PPM sheets (3 panels + 2 gutters of 4 px: 152x27)"
    else bad "gallery --width 48 --height 27 did not write 5 PPM sheets of 152x27"; fi
else bad "examples/gallery.c does not build:"; head -15 "$TMP/gallery.log" | sed 's/^/    /'; fi

# 5. bench/README.md is generated from the committed CSVs (python3, standard library only)
if ! command -v python3 >/dev/null 2>&1; then
    if [ "${CI:-}" = true ]; then bad "python3 missing (Debian package python3): bench/README.md not checked"
    else echo "SKIP bench/README.md generation: python3 missing (Debian package python3)"; fi
    echo "$P passed, $F failed"
    [ "$F" -eq 0 ]
    exit
fi
cp "$BENCH_README" "$TMP/bench.md"
gen=1
for s in sdf lp pt perceptual web; do
    if ! python3 "bench/${s}_tables.py" --write "$TMP/bench.md" >"$TMP/$s.gen.log" 2>&1; then
        gen=0
        bad "bench/${s}_tables.py --write failed: $(head -c 300 "$TMP/$s.gen.log")"
    fi
done
if [ "$gen" -eq 1 ]; then
    if diff -u "$BENCH_README" "$TMP/bench.md" >"$TMP/bench.diff"; then
        ok "$BENCH_README equals what the table scripts write from bench/results/*.csv"
    else
        bad "$BENCH_README differs from what the table scripts write (python3 bench/<x>_tables.py --write):"
        head -20 "$TMP/bench.diff" | sed 's/^/    /'
    fi
fi

echo "$P passed, $F failed"
[ "$F" -eq 0 ]
