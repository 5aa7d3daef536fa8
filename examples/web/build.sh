#!/usr/bin/env bash
# examples/web/build.sh OUT - builds the browser demo into OUT (make web: build/web):
#   OUT/{sdf,lp,pt}.wasm         scalar builds (no -msimd128: MVP instructions only)
#   OUT/{sdf,lp,pt}.simd.wasm    SIMD128 builds (-msimd128: the headers' __wasm_simd128__ paths)
#   OUT/gaze.wasm                the page's gaze filter and margin (web_gaze.c)
#   OUT/index.html, OUT/demo.js  the page (copied) and OUT/sizes.json (module sizes in bytes)
# clang --target=wasm32 -ffreestanding -nostdlib, no libc and no emscripten: the headers'
# FOV_NO_LIBM math, examples/web/web_rt.h for memset/memcpy/memmove and the allocator, and
# only the exports the glue names (WEB_EXPORT). Needs clang and wasm-ld (Debian: clang lld).
set -eu
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
OUT=${1:-$ROOT/build/web}
SRC=$ROOT/examples/web
CLANG=${CLANG:-clang}
mkdir -p "$OUT"
FLAGS=(--target=wasm32 -std=c99 -O2 -ffp-contract=off -ffreestanding -nostdlib
       -Wall -Wextra -Wshadow -Wdouble-promotion -Werror
       -Wl,--no-entry -Wl,--strip-all -Wl,-z,stack-size=1048576)
# the modules build in parallel; one whose output is newer than all its inputs is kept
one() { # NAME OUTPUT FLAGS...
    local m=$1 out=$2 dep; shift 2
    if [ -f "$out" ]; then
        local fresh=1
        for dep in "$SRC/web_$m.c" "$SRC/web_rt.h" "$ROOT"/fov*.h "$SRC/build.sh"; do
            [ "$dep" -nt "$out" ] && fresh=0
        done
        [ $fresh = 1 ] && return 0
    fi
    "$CLANG" "${FLAGS[@]}" "$@" "$SRC/web_$m.c" -o "$out.tmp" && mv "$out.tmp" "$out"
}
pids=()
for m in sdf lp pt; do
    one "$m" "$OUT/$m.wasm" & pids+=($!)
    one "$m" "$OUT/$m.simd.wasm" -msimd128 & pids+=($!)
done
one gaze "$OUT/gaze.wasm" & pids+=($!)   # the page's gaze filter (scalar: nothing to vectorise)
rc=0
for p in "${pids[@]}"; do wait "$p" || rc=1; done
[ $rc = 0 ] || { echo "examples/web/build.sh: a module failed to build" >&2; exit 1; }
sizes="{"
sep=""
for m in sdf lp pt; do
    a=$(wc -c < "$OUT/$m.wasm"); b=$(wc -c < "$OUT/$m.simd.wasm")
    sizes="$sizes$sep\"$m\": $a, \"$m.simd\": $b"
    sep=", "
done
echo "$sizes}" > "$OUT/sizes.json"
cp "$SRC/index.html" "$SRC/demo.js" "$OUT/"
echo "web demo in $OUT: module sizes (bytes) $(cat "$OUT/sizes.json")"
