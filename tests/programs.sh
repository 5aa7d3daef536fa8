#!/usr/bin/env bash
# Every program a user runs (examples/*.c, bench/*.c, tests/heads_hashes.c,
# tests/flip_reference/gen_images.c, tests/xtarget/compare.c): built, `--help` and `-h` print a
# usage text naming its options to stdout and exit 0, an unknown option prints the usage to
# stderr and exits 2. And every example builds copied out of the repository alone: the example
# with the fov headers and examples/*.h in one empty directory, nothing else on the include path.
# The examples are compiled once, copied out alone (the same files and flags as in the
# repository): their --help / -h / unknown-option checks run on those binaries.
set -u
cd "$(dirname "$0")/.."
B=build/programs
rm -rf "$B"; mkdir -p "$B"
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
CC=${CC:-gcc}
STD="-std=c99 -D_POSIX_C_SOURCE=200809L -O0 -Wall -Wextra -Werror"

JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
# the builds run JOBS at a time: build NAME DIR SOURCE FLAGS... compiles in DIR in the
# background and leaves the exit status in DIR/NAME.rc
build() {
    local name=$1 dir=$2 src=$3; shift 3
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    ( cd "$dir" && $CC $STD "$src" -o "$name" "$@" -lm -pthread >"$name.build.log" 2>&1
      echo $? >"$name.rc" ) &
}
R=$(pwd)
for f in bench/*.c; do build "$(basename "$f" .c)" "$B" "$R/$f" -I"$R" -I"$R/bench"; done
build heads_hashes "$B" "$R/tests/heads_hashes.c" -I"$R"
build gen_images "$B" "$R/tests/flip_reference/gen_images.c" -I"$R/tests/common"
build compare "$B" "$R/tests/xtarget/compare.c"
# the examples copied out alone: the example with the fov headers and examples/*.h
for f in examples/*.c; do
    name=$(basename "$f" .c) d=$B/alone_$(basename "$f" .c)
    mkdir -p "$d"; cp fov*.h examples/*.h "$f" "$d/"
    build "$name" "$d" "$name.c"
done
wait

# NAME [DIR]: the program built above (in DIR, default $B)
program() {
    local name=$1 dir=${2:-$B} out err rc
    if [ "$(cat "$dir/$name.rc" 2>/dev/null)" != 0 ]; then
        bad "$name builds: $(head -3 "$dir/$name.build.log" | tr '\n' ' ')"; return
    fi
    for h in --help -h; do
        out=$("$dir/$name" $h 2>"$dir/$name.err"); rc=$?
        if [ "$rc" -eq 0 ] && echo "$out" | grep -q '^usage: ' && [ "$(echo "$out" | wc -l)" -ge 2 ] \
           && [ ! -s "$dir/$name.err" ]; then
            ok "$name $h: exit 0, $(echo "$out" | wc -l) lines of usage on stdout"
        else
            bad "$name $h: exit $rc, stdout '$(echo "$out" | head -2 | tr '\n' ' ')'"
        fi
    done
    out=$("$dir/$name" --no-such-option 2>"$dir/$name.err"); rc=$?
    if [ "$rc" -eq 2 ] && grep -q '^usage: ' "$dir/$name.err" && [ -z "$out" ]; then
        ok "$name --no-such-option: exit 2, usage on stderr"
    else
        bad "$name --no-such-option: exit $rc, stderr '$(head -2 "$dir/$name.err" | tr '\n' ' ')'"
    fi
}

for f in examples/*.c; do program "$(basename "$f" .c)" "$B/alone_$(basename "$f" .c)"; done
for f in bench/*.c; do program "$(basename "$f" .c)"; done
program heads_hashes
program gen_images
program compare

# the examples copied out alone
for f in examples/*.c; do
    name=$(basename "$f" .c) d=$B/alone_$(basename "$f" .c)
    if [ "$(cat "$d/$name.rc" 2>/dev/null)" = 0 ]; then
        ok "$name builds alone from the fov headers and examples/*.h"
    else
        bad "$name does not build alone: $(head -3 "$d/$name.build.log" | tr '\n' ' ')"
    fi
done
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
