#!/usr/bin/env bash
# The examples build warning-free, sdf_basic writes a valid image, and the scenes demo (in
# --check mode, at a small size) matches the ground truth with every tracer on every scene.
set -u
cd "$(dirname "$0")/.."
mkdir -p build/examples
P=0; F=0
ok() { echo "PASS $1"; P=$((P + 1)); }
bad() { echo "FAIL $1"; F=$((F + 1)); }
CC=${CC:-gcc}
W="-Wall -Wextra -Wpedantic -Wshadow -Wconversion -Wdouble-promotion -Werror"
if $CC -std=c99 -O2 $W -I. examples/sdf_basic.c -lm -o build/examples/sdf_basic; then ok "sdf_basic builds with $W"; else bad "sdf_basic build"; fi
if [ -x build/examples/sdf_basic ] && build/examples/sdf_basic > build/examples/basic.ppm 2>/dev/null \
   && [ "$(head -c 15 build/examples/basic.ppm)" = "$(printf 'P6\n320 240\n255')" ] \
   && [ "$(stat -c %s build/examples/basic.ppm)" -eq $((15 + 320 * 240 * 3)) ]; then
    ok "sdf_basic writes a 320x240 PPM"
else
    bad "sdf_basic output"
fi
if $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -Wall -Wextra -Werror -I. examples/sdf_scenes.c -lm -pthread -o build/examples/sdf_scenes; then
    ok "sdf_scenes builds"
    out=$(build/examples/sdf_scenes --width 160 --height 90 --check --no-images 2>&1)
    echo "$out" | grep -E '^(PASS|FAIL)'
    P=$((P + $(echo "$out" | grep -c '^PASS')))
    F=$((F + $(echo "$out" | grep -c '^FAIL')))
    n=$(echo "$out" | grep -cE '^(PASS|FAIL)')
    if [ "$n" -ne 54 ]; then bad "sdf_scenes --check ran $n of 54 checks (6 scenes x 9 methods)"; fi
else
    bad "sdf_scenes build"
fi
if $CC -std=c99 -O2 $W -I. examples/pt_basic.c -lm -o build/examples/pt_basic; then ok "pt_basic builds with $W"; else bad "pt_basic build"; fi
if [ -x build/examples/pt_basic ] && build/examples/pt_basic > build/examples/pt_basic.ppm 2>/dev/null \
   && [ "$(head -c 15 build/examples/pt_basic.ppm)" = "$(printf 'P6\n320 240\n255')" ] \
   && [ "$(stat -c %s build/examples/pt_basic.ppm)" -eq $((15 + 320 * 240 * 3)) ]; then
    ok "pt_basic writes a 320x240 PPM"
else
    bad "pt_basic output"
fi
if $CC -std=c99 -D_POSIX_C_SOURCE=200809L -O2 -Wall -Wextra -Werror -I. -Ibench bench/bench_pt.c -lm -pthread -o build/examples/bench_pt; then
    ok "bench_pt builds"
else
    bad "bench_pt build"
fi
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
