#!/usr/bin/env bash
# Every program a user runs (examples/*.c, bench/*.c, tests/heads_hashes.c,
# tests/flip_reference/gen_images.c, tests/xtarget/compare.c): built, `--help` and `-h` print a
# usage text naming its options to stdout and exit 0, an unknown option prints the usage to
# stderr and exits 2. And every example builds copied out of the repository alone: the example
# with the fov headers and examples/*.h in one empty directory, nothing else on the include path.
set -u
cd "$(dirname "$0")/.."
B=build/programs
rm -rf "$B"; mkdir -p "$B"
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
CC=${CC:-gcc}
STD="-std=c99 -D_POSIX_C_SOURCE=200809L -O0 -Wall -Wextra -Werror"

# NAME SOURCE FLAGS...
program() {
    local name=$1 src=$2 out err rc; shift 2
    if ! $CC $STD "$src" -o "$B/$name" "$@" -lm -pthread >"$B/$name.build.log" 2>&1; then
        bad "$name builds: $(head -3 "$B/$name.build.log" | tr '\n' ' ')"; return
    fi
    for h in --help -h; do
        out=$("$B/$name" $h 2>"$B/$name.err"); rc=$?
        if [ "$rc" -eq 0 ] && echo "$out" | grep -q '^usage: ' && [ "$(echo "$out" | wc -l)" -ge 2 ] \
           && [ ! -s "$B/$name.err" ]; then
            ok "$name $h: exit 0, $(echo "$out" | wc -l) lines of usage on stdout"
        else
            bad "$name $h: exit $rc, stdout '$(echo "$out" | head -2 | tr '\n' ' ')'"
        fi
    done
    out=$("$B/$name" --no-such-option 2>"$B/$name.err"); rc=$?
    if [ "$rc" -eq 2 ] && grep -q '^usage: ' "$B/$name.err" && [ -z "$out" ]; then
        ok "$name --no-such-option: exit 2, usage on stderr"
    else
        bad "$name --no-such-option: exit $rc, stderr '$(head -2 "$B/$name.err" | tr '\n' ' ')'"
    fi
}

for f in examples/*.c; do program "$(basename "$f" .c)" "$f" -I.; done
for f in bench/*.c; do program "$(basename "$f" .c)" "$f" -I. -Ibench; done
program heads_hashes tests/heads_hashes.c -I.
program gen_images tests/flip_reference/gen_images.c -Itests/common
program compare tests/xtarget/compare.c

# the examples copied out alone
for f in examples/*.c; do
    name=$(basename "$f" .c) d=$B/alone_$(basename "$f" .c)
    mkdir -p "$d"; cp fov*.h examples/*.h "$f" "$d/"
    if (cd "$d" && $CC $STD "$name.c" -o "$name" -lm -pthread >build.log 2>&1); then
        ok "$name builds alone from the fov headers and examples/*.h"
    else
        bad "$name does not build alone: $(head -3 "$d/build.log" | tr '\n' ' ')"
    fi
done
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
