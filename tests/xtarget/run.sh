#!/usr/bin/env bash
# tests/xtarget/run.sh - the same fovsdf render on other targets, compared with the host.
#
# Run from the repository root:   bash tests/xtarget/run.sh
# Prints one line per check (PASS name / FAIL name: detail / SKIP name: reason (apt-get
# install PKG)) and ends with exactly "N passed, N failed" (SKIPs are not counted); exit
# status 1 when anything failed. With CI=true a missing toolchain is a FAIL, not a SKIP.
# Build products go to build/xtarget/ only (recreated on every run); the measured figures
# are also written to build/xtarget/figures.txt, the images to build/xtarget/<target>/*.ppm.
# JOBS=n: parallel target jobs (default: the number of CPUs). WASI_SYSROOT=dir overrides the
# wasi-libc sysroot search.
#
# What is checked:
#   render_test.c (public fovsdf API only) renders FOVSDF_SCENE_PRIMITIVES and
#   FOVSDF_SCENE_THIN at 96x54, 1 spp, classic tracer, fovsdf_config_default(), from static
#   memory (no malloc; the fovsdf_builtin_size() query is checked against it), and dumps the
#   8-bit sRGB image, hit mask, depth (float bits) and evaluation counts as text on stdout.
#   When fovlp.h exists it also dumps three fovlp reconstructions (lp_render_test.h: C Fov,
#   K Fov, C Fov with 4 TAA frames, of a triangle-wave image) as scenes 20-22, compared the
#   same way (PSNR >= 50 dB).
#   Builds, all with -O2 -ffp-contract=off:
#     native            gcc, hosted, libm: the reference
#     native-nolibm     gcc, hosted, -DFOV_NO_LIBM (the built-in approximations alone)
#     wasm32-libm       clang --target=wasm32-wasi --sysroot=<wasi-libc>, wasi-libc's libm,
#                       run by node's WASI (run_wasi.mjs)
#     wasm32-nolibm     the same with -DFOV_NO_LIBM
#     cortex-m4-nolibm  arm-none-eabi-gcc -mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16
#                       -mfloat-abi=hard -ffreestanding -DFOV_NO_LIBM -nostdlib, own startup
#                       (m4_startup.c: vectors, FPU enable, .data/.bss, semihosting) and
#                       linker script (mps2_an386.ld), run by
#                       qemu-system-arm -M mps2-an386 -nographic -semihosting (timeout 300 s)
#     cortex-m4-libm    the same linked with newlib's hard-float libm (no FOV_NO_LIBM)
#   The same six builds of render_test_pt.c, plus wasm32-simd128 (wasm32-libm with -msimd128:
#   fovpt's SIMD128 traversal), (public fovpt API only: a Cornell-like box with
#   a 128-triangle mesh behind a BVH, UNIFORM path tracing at 2 spp (the SOBOL sampler) and SELECTIVE with the
#   Whitted tracer, 64x36; hit/depth from fovpt_intersect of the pixel-centre rays) run as
#   targets pt-<name>, compared with pt-native at PSNR >= 35 dB (PSNR_MIN_PT) and the same
#   hit-mask bound.
#   Each build is a check (compile and link), each run is a check (exit status 0 and a
#   complete dump), and compare.c compares each scene of each target with the native
#   reference: PASS when PSNR >= 50 dB and hit-mask mismatch <= 0.1 %; it also reports the
#   largest depth difference over pixels both mark as hit and the evaluation counts.
#
#   mem_test.c renders FOVSDF_SCENE_PRIMITIVES at 160x128 with the cone pyramid (full shading)
#   band by band from a bump-allocated arena (compacted program, context, one band of
#   outputs) and measures the stack high-water mark on the Cortex-M4: PASS when arena +
#   stack <= 32768 bytes; its image is compared with the native build of the same program.
#
#   bvh-wasm32, bvh-wasm32-simd128, bvh-aarch64-neon: tests/test_fovpt.c's BVH = brute force
#   sections (-DFOVPT_TEST_BVH_ONLY) built for each SIMD path of fovpt's traversal (scalar,
#   SIMD128, NEON) and run (node; qemu-aarch64 for the static AArch64 build).
#
# Debian packages: gcc clang lld wasi-libc libclang-rt-dev-wasm32 nodejs (>= 20)
# gcc-arm-none-eabi libnewlib-arm-none-eabi qemu-system-arm gcc-aarch64-linux-gnu
# libc6-dev-arm64-cross qemu-user.

set -u
ROOT=$(cd "$(dirname "${BASH_SOURCE[0]}")/../.." && pwd)
cd "$ROOT" || exit 1
B=build/xtarget
T=tests/xtarget
rm -rf "$B"
mkdir -p "$B/res"
JOBS=${JOBS:-$(nproc 2>/dev/null || echo 2)}
IS_CI=0
[ "${CI:-}" = true ] && IS_CI=1
START=$(date +%s)

COMMON=(-O2 -ffp-contract=off -Wall -Wextra -I. -I"$T")
# fovlp.h present: render_test.c also renders its scenes (tests/xtarget/lp_render_test.h)
[ -f fovlp.h ] && COMMON+=(-DXT_FOVLP)
M4FLAGS=(-mcpu=cortex-m4 -mthumb -mfpu=fpv4-sp-d16 -mfloat-abi=hard)
PSNR_MIN=50
# fovpt (pt-* targets): path tracing amplifies last-ulp libm differences into other paths
# (Russian roulette, lobe choices), so the bound is lower; measured: see figures.txt
PSNR_MIN_PT=35
HIT_MAX=0.1

say() { printf '%s\n' "$*"; }
pass() { if [ $# -gt 1 ]; then say "PASS $1: $2"; else say "PASS $1"; fi; }
fail() { say "FAIL $1: $2"; }
missing() { # NAME WHAT PKG
    if [ "$IS_CI" = 1 ]; then
        fail "$1" "$2 not found (CI=true: a missing toolchain is a failure; apt-get install $3)"
    else
        say "SKIP $1: $2 not found (apt-get install $3)"
    fi
}
need() { # NAME TOOL PKG
    command -v "$2" >/dev/null 2>&1 && return 0
    missing "$1" "$2" "$3"
    return 1
}
errsum() {
    local s
    s=$(grep -E 'error|Error|undefined|warning: .*double' "$1" | head -n 3)
    [ -n "$s" ] || s=$(head -n 3 "$1")
    s=$(printf '%s' "$s" | tr '\n' '|' | sed 's/|/ | /g')
    printf '%s (log: %s)' "${s:0:600}" "$1"
}
now_ms() { date +%s%3N; }

# ---- toolchain discovery --------------------------------------------------------------
find_wasi_sysroot() {
    local d
    for d in ${WASI_SYSROOT:-} /usr/share/wasi-sysroot /opt/wasi-sdk/share/wasi-sysroot \
             /usr/local/share/wasi-sysroot /usr/lib/wasi-sdk/share/wasi-sysroot /usr; do
        if [ -f "$d/lib/wasm32-wasi/libc.a" ] || { [ -f "$d/lib/libc.a" ] && [ -d "$d/include/wasi" ]; }; then
            echo "$d"
            return 0
        fi
    done
    return 1
}

# wasm_build_tools NAME: clang, wasm-ld, wasi-libc and the wasm32 builtins
wasm_build_tools() {
    need "$1" clang clang || return 1
    need "$1" wasm-ld lld || return 1
    WASI_SR=$(find_wasi_sysroot) || { missing "$1" "the wasi-libc sysroot (wasm32-wasi/libc.a)" wasi-libc; return 1; }
    local rt
    rt=$(clang --target=wasm32-wasi --sysroot="$WASI_SR" -print-libgcc-file-name 2>/dev/null)
    if [ -z "$rt" ] || [ ! -f "$rt" ]; then
        missing "$1" "libclang_rt.builtins-wasm32.a" libclang-rt-dev-wasm32; return 1
    fi
    return 0
}

# wasm_run_tools NAME: node >= 20 (node:wasi with version 'preview1')
wasm_run_tools() {
    need "$1" node nodejs || return 1
    local major
    major=$(node -p 'process.versions.node.split(".")[0]' 2>/dev/null)
    if [ -z "$major" ] || [ "$major" -lt 20 ]; then
        missing "$1" "node >= 20 (node:wasi preview1; found $(node --version 2>/dev/null))" nodejs
        return 1
    fi
    return 0
}

m4_build_tools() { # NAME LIBM(0/1)
    need "$1" arm-none-eabi-gcc gcc-arm-none-eabi || return 1
    if [ "$2" = 1 ]; then
        local lm
        lm=$(arm-none-eabi-gcc "${M4FLAGS[@]}" -print-file-name=libm.a 2>/dev/null)
        if [ "$lm" = libm.a ] || [ ! -f "$lm" ]; then
            missing "$1" "newlib's libm.a for thumb/v7e-m+fp/hard" libnewlib-arm-none-eabi; return 1
        fi
    fi
    return 0
}

m4_run_tools() { # NAME
    need "$1" qemu-system-arm qemu-system-arm || return 1
    if ! qemu-system-arm -M help 2>/dev/null | grep -q '^mps2-an386'; then
        missing "$1" "qemu-system-arm with the mps2-an386 machine (QEMU >= 6.0)" qemu-system-arm
        return 1
    fi
    return 0
}

# ---- one target: build, run, compare -----------------------------------------------------
# target NAME: prints the build, run and compare lines for NAME
target() {
    local name=$1 d="$B/$1" t0 t1 rc dur base=$1 src="$T/render_test.c"
    # pt-<target>: the same target with the fovpt program (render_test_pt.c)
    if [ "${name#pt-}" != "$name" ]; then base=${name#pt-}; src="$T/render_test_pt.c"; fi
    RUNCHECK=true
    mkdir -p "$d"
    case "$base" in
        native|native-nolibm)
            need "build $name" gcc gcc || return 0
            local defs=()
            [ "$base" = native-nolibm ] && defs=(-DFOV_NO_LIBM)
            if ! gcc -std=c99 "${COMMON[@]}" "${defs[@]}" "$src" -o "$d/prog" -lm \
                > "$d/build.log" 2>&1; then
                fail "build $name" "$(errsum "$d/build.log")"; return 0
            fi
            RUN=(timeout 120 "$d/prog")
            ;;
        wasm32-libm|wasm32-nolibm|wasm32-simd128)
            wasm_build_tools "build $name" || return 0
            local defs=(-lm)
            [ "$base" = wasm32-nolibm ] && defs=(-DFOV_NO_LIBM)
            [ "$base" = wasm32-simd128 ] && defs=(-lm -msimd128)
            if ! clang --target=wasm32-wasi --sysroot="$WASI_SR" -std=c99 "${COMMON[@]}" \
                "$src" "${defs[@]}" -o "$d/prog.wasm" > "$d/build.log" 2>&1; then
                fail "build $name" "$(errsum "$d/build.log")"; return 0
            fi
            RUN=(timeout 300 node "$T/run_wasi.mjs" "$d/prog.wasm")
            RUNCHECK=wasm_run_tools
            ;;
        cortex-m4-nolibm|cortex-m4-libm)
            local libm=0
            [ "$base" = cortex-m4-libm ] && libm=1
            m4_build_tools "build $name" "$libm" || return 0
            # shellcheck disable=SC2054
            local cmd=(arm-none-eabi-gcc "${M4FLAGS[@]}" -std=c99 "${COMMON[@]}" -DXT_SEMIHOSTING
                       -nostartfiles -T "$T/mps2_an386.ld" -Wl,--gc-sections -ffunction-sections
                       -fdata-sections "$T/m4_startup.c" "$src")
            if [ $libm = 1 ]; then
                cmd+=(-DXT_HAVE_LIBC -o "$d/prog.elf" -lm -lc -lgcc)
            else
                cmd+=(-ffreestanding -DFOV_NO_LIBM -nostdlib -o "$d/prog.elf" -lgcc)
            fi
            if ! "${cmd[@]}" > "$d/build.log" 2>&1; then
                fail "build $name" "$(errsum "$d/build.log")"; return 0
            fi
            # an image that touches double-precision helpers would run, but slowly: report it
            if command -v arm-none-eabi-nm >/dev/null 2>&1; then
                arm-none-eabi-nm "$d/prog.elf" | awk '{print $NF}' |
                    grep -E '^(__aeabi_d|__aeabi_[a-z0-9]*2d$|__extendsfdf2|__truncdfsf2)' \
                    > "$d/double_helpers.txt" || true
            fi
            RUN=(timeout 300 qemu-system-arm -M mps2-an386 -nographic -semihosting -kernel "$d/prog.elf")
            RUNCHECK=m4_run_tools
            ;;
        *) fail "$name" "unknown target"; return 0 ;;
    esac
    local info=""
    [ -f "$d/prog.elf" ] && info=", $(arm-none-eabi-size "$d/prog.elf" 2>/dev/null | awk 'NR==2{print "text " $1 " B, data " $2 " B, bss " $3 " B"}')"
    [ -s "$d/double_helpers.txt" ] && info="$info; links double helpers: $(tr '\n' ' ' < "$d/double_helpers.txt")"
    [ -f "$d/prog.wasm" ] && info=", $(wc -c < "$d/prog.wasm") B"
    pass "build $name" "ok${info}"

    "$RUNCHECK" "run $name" || return 0
    t0=$(now_ms)
    "${RUN[@]}" < /dev/null > "$d/out.txt" 2> "$d/run.err"
    rc=$?
    t1=$(now_ms)
    dur=$(awk -v a="$t0" -v b="$t1" 'BEGIN{printf "%.1f", (b - a) / 1000}')
    if [ $rc != 0 ]; then
        local why="exit status $rc"
        [ $rc = 124 ] && why="timeout (hang?)"
        fail "run $name" "$why after $dur s; stderr: $(head -c 300 "$d/run.err" | tr '\n' ' '); stdout tail: $(tail -c 200 "$d/out.txt" | tr '\n' ' ') (log: $d/)"
        return 0
    fi
    if ! grep -q '^done 0$' "$d/out.txt"; then
        fail "run $name" "no 'done 0' line in $d/out.txt: $(grep -E '^(status|error)' "$d/out.txt" | tr '\n' ' ')"
        return 0
    fi
    pass "run $name" "$dur s; scene memory (bytes): $(awk '/^scene /{n=$3} /^memory scene /{printf "%s%s %s", sep, n, $3; sep=", "}' "$d/out.txt") of $(awk '/^memory scene /{print $5; exit}' "$d/out.txt") static"
    echo "$dur" > "$d/seconds"
    if [ "$base" != native ]; then
        compare_with_native "$name"
    fi
}

compare_with_native() {
    local name=$1 ref=native psnr=$PSNR_MIN
    if [ "${name#pt-}" != "$name" ]; then ref=pt-native; psnr=$PSNR_MIN_PT; fi
    # wait for the native reference (run in the first batch; normally done already)
    local i=0
    while [ ! -f "$B/$ref/ready" ] && [ $i -lt 600 ]; do sleep 0.5; i=$((i + 1)); done
    if [ ! -f "$B/$ref/out.txt" ] || ! grep -q '^done 0$' "$B/$ref/out.txt"; then
        fail "compare $name" "no native reference (see the native build/run lines)"; return 0
    fi
    if [ ! -x "$B/compare" ]; then
        fail "compare $name" "the compare tool did not build (see build compare)"; return 0
    fi
    "$B/compare" --psnr "$psnr" --hit "$HIT_MAX" "$name" "$B/$ref/out.txt" "$B/$name/out.txt" \
        > "$B/$name/compare.txt" 2>&1
    local rc=$?
    grep -E '^(PASS|FAIL) ' "$B/$name/compare.txt"
    if ! grep -qE '^(PASS|FAIL) ' "$B/$name/compare.txt" ||
       { [ $rc != 0 ] && ! grep -q '^FAIL ' "$B/$name/compare.txt"; }; then
        fail "compare $name" "compare exit status $rc: $(head -c 300 "$B/$name/compare.txt" | tr '\n' ' ')"
    fi
}

# ---- job runner ---------------------------------------------------------------------------
SEQ=0
job() {
    SEQ=$((SEQ + 1))
    local out
    out=$(printf '%s/res/%04d' "$B" "$SEQ")
    while [ "$(jobs -rp | wc -l)" -ge "$JOBS" ]; do wait -n 2>/dev/null || true; done
    ( "$@" ) > "$out" 2> "$out.err" &
}

build_compare() {
    need "build compare" gcc gcc || return 0
    if ! gcc -std=c99 -O2 -Wall -Wextra -Werror "$T/compare.c" -o "$B/compare.tmp" -lm \
        > "$B/compare.log" 2>&1; then
        fail "build compare" "$(errsum "$B/compare.log")"; return 0
    fi
    mv "$B/compare.tmp" "$B/compare"
    pass "build compare" "tests/xtarget/compare.c"
}

native_ref() {
    target native
    mkdir -p "$B/native"
    touch "$B/native/ready"
}
native_ref_pt() {
    target pt-native
    mkdir -p "$B/pt-native"
    touch "$B/pt-native/ready"
}

if [ ! -f fovsdf.h ]; then
    say "FAIL fovsdf.h: not found in $ROOT"
    say "0 passed, 1 failed"
    exit 1
fi

# mem_test: Primitives at 160x128 with the cone pyramid in at most 32 KiB of working memory
# on the Cortex-M4 (mem_test.c), compared with the same program built natively.
MEM_LIMIT=32768
mem_check() {
    local d="$B/mem" n="mem cortex-m4"
    mkdir -p "$d"
    need "build mem native" gcc gcc || return 0
    if ! gcc -std=c99 "${COMMON[@]}" "$T/mem_test.c" -o "$d/native" -lm > "$d/build_native.log" 2>&1; then
        fail "build mem native" "$(errsum "$d/build_native.log")"; return 0
    fi
    timeout 120 "$d/native" > "$d/native.txt" 2>&1 || { fail "run mem native" "exit status $? (log: $d/native.txt)"; return 0; }
    m4_build_tools "build $n" 0 || return 0
    if ! arm-none-eabi-gcc "${M4FLAGS[@]}" -std=c99 "${COMMON[@]}" -DXT_SEMIHOSTING -nostartfiles -T "$T/mps2_an386.ld" \
        -Wl,--gc-sections -ffunction-sections -fdata-sections "$T/m4_startup.c" "$T/mem_test.c" -ffreestanding \
        -DFOV_NO_LIBM -nostdlib -o "$d/m4.elf" -lgcc > "$d/build_m4.log" 2>&1; then
        fail "build $n" "$(errsum "$d/build_m4.log")"; return 0
    fi
    m4_run_tools "run $n" || return 0
    timeout 300 qemu-system-arm -M mps2-an386 -nographic -semihosting -kernel "$d/m4.elf" < /dev/null > "$d/m4.txt" 2> "$d/m4.err"
    local rc=$?
    if [ $rc != 0 ] || ! grep -q '^done 0$' "$d/m4.txt"; then
        fail "run $n" "exit status $rc; $(grep -E '^(status|error)' "$d/m4.txt" | tr '\n' ' ') (log: $d/)"; return 0
    fi
    local line total stack
    line=$(grep '^memory render ' "$d/m4.txt")
    total=$(echo "$line" | awk '{for (i = 1; i < NF; i++) if ($i == "total") print $(i + 1)}')
    stack=$(echo "$line" | awk '{for (i = 1; i < NF; i++) if ($i == "stack") print $(i + 1)}')
    if [ -n "$total" ] && [ -n "$stack" ] && [ "$stack" -gt 0 ] && [ "$total" -le "$MEM_LIMIT" ]; then
        pass "$n primitives 160x128 cone in <= $MEM_LIMIT B" "${line#memory render }; build (start-up only) $(grep '^memory build ' "$d/m4.txt" | cut -d' ' -f3) B"
    else
        fail "$n primitives 160x128 cone in <= $MEM_LIMIT B" "measured: ${line:-no memory line} (log: $d/m4.txt)"
    fi
    if [ -x "$B/compare" ]; then
        "$B/compare" --psnr "$PSNR_MIN" --hit "$HIT_MAX" "$n" "$d/native.txt" "$d/m4.txt" > "$d/compare.txt" 2>&1
        grep -E '^(PASS|FAIL) ' "$d/compare.txt" || fail "compare $n" "$(head -c 300 "$d/compare.txt")"
    fi
}

# bvh_check NAME: tests/test_fovpt.c's BVH = brute force sections (-DFOVPT_TEST_BVH_ONLY) on
# one SIMD path of fovpt's traversal: wasm32 scalar, wasm32 SIMD128 (node), AArch64 NEON
# (aarch64-linux-gnu-gcc -static, qemu-aarch64); PASS when it ends with "N passed, 0 failed"
bvh_check() {
    local name=$1 d="$B/$1" out
    mkdir -p "$d"
    local src=(-std=c99 -O2 -ffp-contract=off -Wall -Wextra -DFOVPT_TEST_BVH_ONLY -I. -Itests/common
               tests/test_fovpt.c)
    case "$name" in
        bvh-wasm32|bvh-wasm32-simd128)
            wasm_build_tools "build $name" || return 0
            local f=()
            [ "$name" = bvh-wasm32-simd128 ] && f=(-msimd128)
            clang --target=wasm32-wasi --sysroot="$WASI_SR" "${src[@]}" "${f[@]}" -lm \
                -o "$d/prog.wasm" > "$d/build.log" 2>&1 || { fail "build $name" "$(errsum "$d/build.log")"; return 0; }
            wasm_run_tools "run $name" || return 0
            RUN=(timeout 300 node "$T/run_wasi.mjs" "$d/prog.wasm")
            ;;
        bvh-aarch64-neon)
            need "build $name" aarch64-linux-gnu-gcc gcc-aarch64-linux-gnu || return 0
            aarch64-linux-gnu-gcc -static "${src[@]}" -lm -o "$d/prog" > "$d/build.log" 2>&1 ||
                { fail "build $name" "$(errsum "$d/build.log")"; return 0; }
            need "run $name" qemu-aarch64 qemu-user || return 0
            RUN=(timeout 600 qemu-aarch64 "$d/prog") # about 20 s unloaded
            ;;
    esac
    pass "build $name" "ok"
    local rc
    "${RUN[@]}" < /dev/null > "$d/out.txt" 2> "$d/run.err"
    rc=$?
    out=$(tail -n 1 "$d/out.txt")
    [ $rc = 124 ] && out="timeout after $(grep -c '^PASS' "$d/out.txt") checks"
    if [ $rc = 0 ] && echo "$out" | grep -qE '^[0-9]+ passed, 0 failed$'; then
        pass "run $name: BVH = brute force" "$out"
    else
        fail "run $name: BVH = brute force" "$out; $(grep -m 3 '^FAIL' "$d/out.txt" | tr '\n' ' ') (log: $d/)"
    fi
}

# the reference and the compare tool first, then the other targets
job build_compare
job native_ref
[ -f fovpt.h ] && job native_ref_pt
wait
for tgt in cortex-m4-nolibm cortex-m4-libm wasm32-libm wasm32-nolibm native-nolibm; do
    job target "$tgt"
    [ -f fovpt.h ] && job target "pt-$tgt"
done
[ -f fovpt.h ] && job target pt-wasm32-simd128
if [ -f fovpt.h ]; then
    for tgt in bvh-wasm32 bvh-wasm32-simd128 bvh-aarch64-neon; do job bvh_check "$tgt"; done
fi
job mem_check
wait

# images for viewing: build/xtarget/<target>/<scene>.ppm and <scene>_hit.pgm (not checks)
if [ -x "$B/compare" ]; then
    for d in "$B"/*/; do
        [ -f "$d/out.txt" ] && "$B/compare" --ppm "$d/out.txt" "$d" > /dev/null 2>&1
    done
fi

# ---- report -----------------------------------------------------------------------------
passed=0
failed=0
{
    echo "# tests/xtarget figures, $(date -u '+%Y-%m-%d %H:%M:%S UTC'), fovsdf $(grep -m1 -o 'FOVSDF_VERSION_STRING "[^"]*"' fovsdf.h | cut -d'"' -f2)"
    echo "# reference: native gcc -O2 -ffp-contract=off with libm; pass: psnr >= $PSNR_MIN dB, hit mismatch <= $HIT_MAX %"
    echo "# $(gcc --version 2>/dev/null | head -n1); $(clang --version 2>/dev/null | head -n1); $(arm-none-eabi-gcc --version 2>/dev/null | head -n1); $(qemu-system-arm --version 2>/dev/null | head -n1); node $(node --version 2>/dev/null)"
} > "$B/figures.txt"
for f in "$B"/res/[0-9][0-9][0-9][0-9]; do
    [ -f "$f" ] || continue
    if [ ! -s "$f" ]; then
        say "FAIL internal: job $(basename "$f") printed nothing: $(head -c 300 "$f.err")"
        failed=$((failed + 1))
        continue
    fi
    cat "$f"
    grep -E '^(PASS|FAIL|SKIP) ' "$f" >> "$B/figures.txt"
    passed=$((passed + $(grep -c '^PASS ' "$f")))
    failed=$((failed + $(grep -c '^FAIL ' "$f")))
done
say "# $(($(date +%s) - START)) s; figures in $B/figures.txt; dumps and logs in $B/<target>/"
say "$passed passed, $failed failed"
[ "$failed" = 0 ]
