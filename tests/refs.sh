#!/usr/bin/env bash
# Self-contained references: no tracked file cites the project's internal background documents
# (the extracted paper texts and the notes made from them, by file name, number or section),
# which a reader of the repository does not have. Papers are cited by authors, title and year
# (each header's REFERENCES section) and by the paper's own section, equation or figure.
# One check per kind of file (headers, README, docs, bench, examples, tests, build files, other):
# FAIL lists the offending lines. Each header must also have a REFERENCES section.
# Usage: bash tests/refs.sh [REPO_DIR]   (default: this repository)
set -u
ROOT=${1:-"$(dirname "$0")/.."}
cd "$ROOT" || { echo "FAIL cannot enter $ROOT"; echo "0 passed, 1 failed"; exit 1; }
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }

# This file matches its own patterns, so it is left out of the scan.
PAT="seed ?0[0-9]{2}|seed0[0-9]|\bnotes? (seed|section|[0-9])|\bnotes'|notes/"
PAT="$PAT|shared/(seeds|notes)|seeds/|\bboth seeds\b|\bthe seed's"
PAT="$PAT|(^|[ (;])00[0-4]([):,]|'s| (Eq|Table|Fig|sec|ch)\b)|\bas in 00[0-4]\b"

# kind_of FILE: sets K to the kind of FILE (no subshell: this runs once per tracked file)
kind_of() {
    case "$1" in
        README.md) K=README ;;
        fov*.h) K=headers ;;
        docs/*) K=docs ;;
        bench/*) K=bench ;;
        examples/*) K=examples ;;
        tests/*) K=tests ;;
        Makefile|CMakeLists.txt|*.cmake|*.cmake.in|*.pc|*.pc.in|.ci/*|.gitignore) K=build ;;
        *) K=other ;;
    esac
}

files=$(git ls-files 2>/dev/null)
if [ -z "$files" ]; then bad "git ls-files lists no file in $ROOT"; echo "$P passed, $F failed"; exit 1; fi
declare -A NF HITS
while IFS= read -r f; do
    [ -f "$f" ] && [ "$f" != tests/refs.sh ] || continue
    kind_of "$f"; NF[$K]=$(( ${NF[$K]:-0} + 1 ))
done <<< "$files"
# one grep over every tracked text file (-I skips binary files), hits sorted into kinds
all=$(printf '%s\n' "$files" | grep -v -x 'tests/refs.sh' | tr '\n' '\0' \
      | xargs -0 grep -I -n -i -E "$PAT" -- 2>/dev/null | cut -c1-150)
while IFS= read -r line; do
    [ -n "$line" ] || continue
    kind_of "${line%%:*}"; HITS[$K]="${HITS[$K]:-}    $line"$'\n'
done <<< "$all"
for kind in headers README docs bench examples tests build other; do
    n=${NF[$kind]:-0}; hits=${HITS[$kind]:-}
    [ "$n" -eq 0 ] && continue
    if [ -z "$hits" ]; then
        ok "$kind ($n files): no reference to the internal background documents"
    else
        bad "$kind ($n files): $(printf '%s' "$hits" | grep -c .) lines cite internal documents:"
        printf '%s' "$hits" | head -n 40
    fi
done

# every header names the papers it cites in full
for h in fovsdf.h fovlp.h fovpt.h; do
    [ -f "$h" ] || continue
    if grep -q -E "^REFERENCES( |$)" "$h"; then ok "$h has a REFERENCES section"
    else bad "$h has no REFERENCES section in its doc block"; fi
done
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
