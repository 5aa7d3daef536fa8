#!/usr/bin/env bash
# Source style of the headers.
# 1. Line length: lines over 100 characters in fovsdf.h, fovlp.h, fovpt.h and
#    tools/fov_shared.h, against a budget per file (0 for all four since every header was
#    wrapped to 100 columns; never raise it). Every line counts, error messages included.
#    Offending lines are printed.
# 2. Every FOV*__ macro that a header tests with #if / #elif is #defined in that header (an
#    undefined one reads as 0 without a word: an SSE path that silently never compiles).
# Both are also run on a corrupted copy, where they must fail.
set -u
cd "$(dirname "$0")/.."
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT

budget() {
    case "$1" in
    fovsdf.h) echo 0 ;;
    fovlp.h) echo 0 ;;
    fovpt.h) echo 0 ;;
    tools/fov_shared.h) echo 0 ;;
    esac
}

# long FILE: the lines over 100 characters that count, as "file:line: text"
long() {
    awk -v f="$1" 'length($0) > 100 { print f ":" NR ": " $0 }' "$1"
}

# macros FILE: FOV*__ names tested by #if/#elif (outside defined()) but never #defined
undefined_macros() {
    local f=$1 m
    for m in $(grep -E '^[[:space:]]*#[[:space:]]*(el)?if\b' "$f" |
               sed -E 's/defined[[:space:]]*\(?[[:space:]]*[A-Za-z_0-9]+\)?//g' |
               grep -oE '\bFOV[A-Z]*__[A-Z0-9_]+' | sort -u); do
        grep -qE "^[[:space:]]*#[[:space:]]*define[[:space:]]+$m\b" "$f" || echo "$m"
    done
}

for f in fovsdf.h fovlp.h fovpt.h tools/fov_shared.h; do
    n=$(long "$f" | wc -l); b=$(budget "$f")
    if [ "$n" -le "$b" ]; then
        ok "$f: $n lines over 100 characters (budget $b)"
    else
        bad "$f: $n lines over 100 characters, budget $b"
        long "$f" | cut -c1-200 | sed 's/^/  /'
    fi
done

for f in fovsdf.h fovlp.h fovpt.h; do
    u=$(undefined_macros "$f" | tr '\n' ' ')
    if [ -z "$u" ]; then ok "$f: every FOV*__ macro tested by #if is defined"
    else bad "$f: tested by #if but never defined: $u"; fi
done

# the checks must catch a corrupted copy: one more long line, one undefined macro
cp fovsdf.h "$TMP/fovsdf.h"
printf '/* %0120d */\n#if FOVSDF__NEVER_DEFINED\n#endif\n' 0 >> "$TMP/fovsdf.h"
n=$(long "$TMP/fovsdf.h" | wc -l)
if [ "$n" -gt "$(budget fovsdf.h)" ]; then ok "a copy with one more long line exceeds the budget ($n)"
else bad "a copy with one more long line passes the budget ($n)"; fi
u=$(undefined_macros "$TMP/fovsdf.h" | tr '\n' ' ')
if [ "$u" = "FOVSDF__NEVER_DEFINED " ]; then ok "a copy testing an undefined macro is caught ($u)"
else bad "a copy testing an undefined macro: got '$u'"; fi

echo "$P passed, $F failed"
[ "$F" -eq 0 ]
