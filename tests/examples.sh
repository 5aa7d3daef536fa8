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
WP="-D_POSIX_C_SOURCE=200809L -Wall -Wextra -Werror"
# every program is compiled first, JOBS at a time; built NAME tells whether NAME compiled
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
pb() {
    local name=$1 src=$2; shift 2
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    ( $CC -std=c99 -O2 "$@" -I. "$src" -lm -pthread -o "build/examples/$name" \
          >"build/examples/$name.build.log" 2>&1; echo $? >"build/examples/$name.rc" ) &
}
built() {
    if [ "$(cat "build/examples/$1.rc" 2>/dev/null)" = 0 ]; then return 0; fi
    sed 's/^/    /' "build/examples/$1.build.log" | head -10
    return 1
}
rm -f build/examples/*.rc
pb sdf_basic examples/sdf_basic.c $W
pb sdf_scenes examples/sdf_scenes.c $WP
pb pt_basic examples/pt_basic.c $W
pb bench_pt bench/bench_pt.c $WP
pb sdf_stereo examples/sdf_stereo.c $W
pb pt_stereo examples/pt_stereo.c $W
pb lp_sdf examples/lp_sdf.c $W
pb lp_pt examples/lp_pt.c $W
wait
if built sdf_basic; then ok "sdf_basic builds with $W"; else bad "sdf_basic build"; fi
if [ -x build/examples/sdf_basic ] && build/examples/sdf_basic > build/examples/basic.ppm 2>/dev/null \
   && [ "$(head -c 15 build/examples/basic.ppm)" = "$(printf 'P6\n320 240\n255')" ] \
   && [ "$(stat -c %s build/examples/basic.ppm)" -eq $((15 + 320 * 240 * 3)) ]; then
    ok "sdf_basic writes a 320x240 PPM"
else
    bad "sdf_basic output"
fi
if built sdf_scenes; then
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
if built pt_basic; then ok "pt_basic builds with $W"; else bad "pt_basic build"; fi
if [ -x build/examples/pt_basic ] && build/examples/pt_basic > build/examples/pt_basic.ppm 2>/dev/null \
   && [ "$(head -c 15 build/examples/pt_basic.ppm)" = "$(printf 'P6\n640 360\n255')" ] \
   && [ "$(stat -c %s build/examples/pt_basic.ppm)" -eq $((15 + 640 * 360 * 3)) ]; then
    ok "pt_basic writes a 640x360 PPM (denoised)"
else
    bad "pt_basic output"
fi
if built bench_pt; then
    ok "bench_pt builds"
else
    bad "bench_pt build"
fi
# stereo: two off-axis eyes side by side (fovsdf 2 x 160x176, fovpt 2 x 128x144); the two
# halves differ (each eye its own frustum, offset and gaze) and neither is blank
for ex in "sdf_stereo 320 176" "pt_stereo 256 144"; do
    set -- $ex
    if built "$1"; then ok "$1 builds with $W"; else bad "$1 build"; continue; fi
    hdr=$(printf 'P6
%s %s
255' "$2" "$3")
    if build/examples/$1 > build/examples/$1.ppm 2>/dev/null && [ "$(head -c ${#hdr} build/examples/$1.ppm)" = "$hdr" ] \
       && [ "$(stat -c %s build/examples/$1.ppm)" -eq $((${#hdr} + 1 + $2 * $3 * 3)) ] \
       && python3 - "build/examples/$1.ppm" "$2" "$3" <<'PY'
import sys
d = open(sys.argv[1], 'rb').read(); w, h = int(sys.argv[2]), int(sys.argv[3]); px = d[len(d) - w * h * 3:]
left = b''.join(px[y * w * 3:y * w * 3 + w * 3 // 2] for y in range(h))
right = b''.join(px[y * w * 3 + w * 3 // 2:(y + 1) * w * 3] for y in range(h))
sys.exit(0 if left != right and len(set(left)) > 8 and len(set(right)) > 8 else 1)
PY
    then
        ok "$1 writes a ${2}x$3 PPM, two different non-blank eyes"
    else
        bad "$1 output"
    fi
done
# fovlp + fovsdf: frames written, and frame 0 matches a full-resolution render in the gaze disc
if built lp_sdf; then
    ok "lp_sdf builds with $W"
    rm -rf build/examples/lp; mkdir -p build/examples/lp
    for taa in "" "--no-taa"; do
        out=$(build/examples/lp_sdf --width 160 --height 90 --frames 3 --check --out build/examples/lp $taa 2>&1)
        if echo "$out" | grep -q '^PASS lp_sdf check'; then ok "lp_sdf --check $taa: $(echo "$out" | grep '^check:')"; else bad "lp_sdf --check $taa: $(echo "$out" | tail -3 | tr '\n' ' ')"; fi
    done
    n=0
    for i in 000 001 002; do
        f=build/examples/lp/lp_primitives_$i.ppm
        [ -f "$f" ] && [ "$(head -c 14 "$f")" = "$(printf 'P6\n160 90\n255')" ] && [ "$(stat -c %s "$f")" -eq $((14 + 160 * 90 * 3)) ] && n=$((n + 1))
    done
    if [ "$n" -eq 3 ]; then ok "lp_sdf writes 3 numbered 160x90 frames"; else bad "lp_sdf wrote $n of 3 frames"; fi
else
    bad "lp_sdf build"
fi
# fovlp + fovpt: path tracing at the log-polar positions, TAA over frames, a PPM of the last
if built lp_pt; then
    ok "lp_pt builds with $W"
    rm -f build/examples/lp_pt.ppm
    if out=$(build/examples/lp_pt --width 160 --height 120 --frames 3 --out build/examples/lp_pt.ppm 2>&1) \
       && [ "$(head -c 15 build/examples/lp_pt.ppm)" = "$(printf 'P6\n160 120\n255')" ] \
       && [ "$(stat -c %s build/examples/lp_pt.ppm)" -eq $((15 + 160 * 120 * 3)) ] \
       && [ "$(echo "$out" | grep -c '^frame ')" -eq 3 ]; then
        ok "lp_pt writes a 160x120 PPM after 3 frames"
    else
        bad "lp_pt output: $(echo "$out" | tail -2 | tr '\n' ' ')"
    fi
else
    bad "lp_pt build"
fi
echo "$P passed, $F failed"
[ "$F" -eq 0 ]
