#!/usr/bin/env bash
# Source style of the headers.
# 1. Line length: lines over 100 characters in fovsdf.h, fovlp.h, fovpt.h and
#    tools/fov_shared.h, against a budget per file (the lines left when the budget was set;
#    lower it when you wrap more, never raise it). Lines carrying an error message
#    (FOV*__FAIL, fov__err, FOV__MSG) are not counted while STYLE_COUNT_ERRORS is 0 (the
#    default for now); STYLE_COUNT_ERRORS=1 counts them too. Offending lines are printed.
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
COUNT_ERRORS=${STYLE_COUNT_ERRORS:-0}

budget() {
    case "$1" in
    fovsdf.h) echo 44 ;;
    fovlp.h) echo 33 ;;
    fovpt.h) echo 147 ;;
    tools/fov_shared.h) echo 0 ;;
    esac
}

# long FILE: the lines over 100 characters that count, as "file:line: text"
long() {
    awk -v f="$1" -v all="$COUNT_ERRORS" 'length($0) > 100 {
        if (!all && $0 ~ /FOV[A-Z]*__FAIL|fov__err|FOV__MSG/) next
        print f ":" NR ": " $0 }' "$1"
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
