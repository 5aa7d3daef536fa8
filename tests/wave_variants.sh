#!/bin/bash
# wave_variants.sh - the wavefront's images do not depend on how many rays are in flight
# (FOVSDF_WAVE), how many points a batch holds (FOVSDF_BATCH), the SIMD paths (FOVSDF_NO_SIMD),
# how many cones of a CONE tile are in flight (FOVSDF_CONE_SLOTS, 1 by default, 5 and 32 in the
# cone_slots variants, where idle slots take other slots' cells) or the shadow proofs
# (FOVSDF_SHADOW_GROUP 16: on) or the per-tile pruning of built-in programs (FOVSDF_PRUNE_CODE,
# forced on for every tile): tests/test_fovsdf_wave.c built with each variant passes its own
# checks and prints the same "INFO hash" lines as the default build; the evaluation counts
# ("INFO counts") too, for the variants that group rays as the default build does.
cd "$(dirname "$0")/.." || exit 2
CC=${CC:-gcc}
OUT=build/wave_variants
mkdir -p "$OUT"
FL="-std=c99 -O2 -DIMG_W=32 -DIMG_H=18 -DWAVE_HASH_ONLY -ffp-contract=off -Wall -Wextra -Wpedantic -Wshadow -Wconversion -Werror -I. -Itests/common"
pass=0; fail=0
ok() { echo "PASS $1"; pass=$((pass + 1)); }
bad() { echo "FAIL $1: $2"; fail=$((fail + 1)); }
VARIANTS=("batch1_wave16:-DFOVSDF_BATCH=1 -DFOVSDF_WAVE=16" "batch7_wave40:-DFOVSDF_BATCH=7 -DFOVSDF_WAVE=40"
          "batch64_wave256:-DFOVSDF_BATCH=64 -DFOVSDF_WAVE=256" "no_simd:-DFOVSDF_NO_SIMD"
          "batch5:-DFOVSDF_BATCH=5" "proofs16:-DFOVSDF_SHADOW_GROUP=16"
          "cone_slots5:-DFOVSDF_CONE_SLOTS=5" "cone_slots32:-DFOVSDF_CONE_SLOTS=32"
          "prune:-DFOVSDF_PRUNE_CODE=512 -DFOVSDF_PRUNE_MIN=0")
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
# every variant built and run first, JOBS at a time (name.rc: the compiler's exit status)
build_run() { # name, flags
    if $CC $FL $2 tests/test_fovsdf_wave.c -o "$OUT/$1" -lm 2>"$OUT/$1.err"; then
        echo 0 >"$OUT/$1.rc"
        "$OUT/$1" >"$OUT/$1.txt" 2>&1
    else
        echo 1 >"$OUT/$1.rc"
    fi
}
rm -f "$OUT"/*.rc "$OUT"/*.txt
for v in "default:" "${VARIANTS[@]}"; do
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    build_run "${v%%:*}" "${v#*:}" &
done
wait
check() { # name: its build and own checks; its hash and counts lines
    if [ "$(cat "$OUT/$1.rc" 2>/dev/null)" != 0 ]; then
        bad "$1_builds" "$(head -3 "$OUT/$1.err")"; return 1
    fi
    if grep -q '^[0-9]* passed, 0 failed' "$OUT/$1.txt"; then ok "$1_own_checks"
    else bad "$1_own_checks" "$(grep '^FAIL' "$OUT/$1.txt" | head -3)"; fi
    grep '^INFO hash' "$OUT/$1.txt" >"$OUT/$1.hash"
    grep '^INFO counts' "$OUT/$1.txt" >"$OUT/$1.counts"
}
check default
n=$(wc -l <"$OUT/default.hash")
[ "$n" -ge 54 ] && ok "default_prints_hashes" || bad "default_prints_hashes" "$n lines"
for v in "${VARIANTS[@]}"; do
    name=${v%%:*}
    check "$name" || continue
    if cmp -s "$OUT/default.hash" "$OUT/$name.hash"; then ok "${name}_same_images"
    else bad "${name}_same_images" "$(diff "$OUT/default.hash" "$OUT/$name.hash" | head -2 | tr '\n' ' ')"; fi
    case $name in no_simd|batch5|prune)
        if cmp -s "$OUT/default.counts" "$OUT/$name.counts"; then ok "${name}_same_counts"
        else bad "${name}_same_counts" "$(diff "$OUT/default.counts" "$OUT/$name.counts" | head -2 | tr '\n' ' ')"; fi;;
    esac
done
echo "$pass passed, $fail failed"
[ "$fail" -eq 0 ]
